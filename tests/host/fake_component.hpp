// A stand-in for the real-time component on a shared memq:// LCM: takes FIRTP_BLOCK and
// FIRTP_CONTROL (checking their crc first, as the bridge), answers FIRTP_STATUS by the rules in
// status_t.lcm / block_t.lcm, publishes FIRTP_AXIS_STATE (all sealed), and can be told to lose, duplicate or reorder blocks or to fall silent.
#pragma once

#include <firtp_lcm/axis_state_t.hpp>
#include <firtp_lcm/block_t.hpp>
#include <firtp_lcm/control_t.hpp>
#include <firtp_lcm/status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <deque>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace firtp::host::test {

class FakeComponent {
public:
    explicit FakeComponent(lcm::LCM& lcm, int capacity = 8);
    ~FakeComponent();
    FakeComponent(const FakeComponent&) = delete;
    FakeComponent& operator=(const FakeComponent&) = delete;

    void tick();  // one servo period: control, execution, axis state, status

    // Faults in transit (each seq once).
    std::set<std::int64_t> drop_once;
    std::set<std::int64_t> duplicate_once;
    std::set<std::int64_t> delay_once;  // delivered right after the next block (reordering)
    struct Refusal {
        std::int64_t seq;
        std::int32_t code;
        std::string text;
    };
    std::optional<Refusal> refuse_always;  // this seq is refused so every time
    int drop_controls = 0;              // control messages lost in transit
    bool silent = false;                // publishes nothing
    bool torn_next = false;             // the next status reads idle and empty (a bridge's torn read)
    int ticks_per_block = 2;            // execution time of a block
    std::int64_t skip_axis_seq = 0;     // this axis-state seq is never published
    void fail(std::string text);        // state ERROR from the next status on
    void refuse_next(std::int32_t code, std::string text);  // the next block is refused so
    void preload(std::int64_t program, int blocks);         // another program already queued

    // What happened.
    std::vector<std::int64_t> received;  // seqs that arrived (after transit faults)
    std::vector<firtp_lcm::block_t> accepted;
    std::vector<firtp_lcm::control_t> controls;
    std::int64_t executed = 0;           // blocks finished (not dropped)
    std::int64_t rejected = 0, repeats = 0, gaps = 0, queue_full = 0;
    std::int64_t corrupted = 0;          // blocks and controls whose crc did not match (refused, ignored)
    int max_depth = 0;
    std::int64_t window_violations = 0;  // seq >= next_seq + queue_free of the newest status sent
    std::int64_t axis_published = 0;
    std::int64_t program = 0;
    std::int64_t next_seq = 1;
    std::int8_t state = firtp_lcm::status_t::IDLE;
    int depth() const { return static_cast<int>(queue_.size()); }
    bool hold() const { return hold_; }
    bool abort() const { return abort_; }
    double feed_scale() const { return feed_scale_; }

private:
    void on_block_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel);
    void on_control_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel);
    void on_block(const firtp_lcm::block_t* message);
    void on_control(const firtp_lcm::control_t* message);
    void receive(const firtp_lcm::block_t& message);
    void refuse(std::int32_t code, const std::string& text);
    void publish_status();
    void publish_axis_state();

    lcm::LCM& lcm_;
    int capacity_;
    lcm::Subscription* block_subscription_;
    lcm::Subscription* control_subscription_;
    std::deque<firtp_lcm::block_t> queue_;
    std::vector<firtp_lcm::block_t> delayed_;
    int ticks_in_block_ = 0;
    std::int64_t window_end_ = 0;  // next_seq + queue_free of the newest status, 0 before one
    std::int64_t tick_ = 0, status_seq_ = 0, axis_seq_ = 0, control_seq_ = 0;
    double feed_scale_ = 1.0;
    bool hold_ = false, abort_ = false;
    std::int32_t error_code_ = 0;
    std::string error_text_;
    std::optional<std::pair<std::int32_t, std::string>> refusal_;
};

}  // namespace firtp::host::test
