// The LCM side of firtp: channels, opening a transport, and turning messages into blocks with
// every check a machine needs (finite values, ranges, known types, sequence).
#pragma once

#include <firtp/types.hpp>
#include <firtp_lcm/axis_state_t.hpp>
#include <firtp_lcm/block_t.hpp>
#include <firtp_lcm/control_t.hpp>
#include <firtp_lcm/status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace firtp::messages {

inline constexpr const char* block_channel = "FIRTP_BLOCK";
inline constexpr const char* status_channel = "FIRTP_STATUS";
inline constexpr const char* axis_state_channel = "FIRTP_AXIS_STATE";            // every servo period
inline constexpr const char* axis_state_live_channel = "FIRTP_AXIS_STATE_LIVE";  // decimated
inline constexpr const char* control_channel = "FIRTP_CONTROL";

// LCM's default multicast group with ttl=0 (this host only) and an 8 MiB receive buffer.
std::string default_url();

// Opens a transport; for udpm:// URLs without recv_buf_size, adds 8 MiB (LCM 1.3.1 loses fast
// streams otherwise). Throws std::runtime_error naming the URL when LCM cannot start (e.g. no
// multicast route).
std::unique_ptr<lcm::LCM> open(const std::string& url);

// Raises a subscription's queue to unbounded (LCM 1.3.1 defaults to 30 and drops the rest).
void keep_everything(lcm::Subscription* subscription);

firtp_lcm::block_t to_message(const Block& block, std::int64_t program, std::int64_t seq, std::int64_t utime);

// Empty when the message can be planned; otherwise what is wrong, naming seq and line, e.g.
// "block seq 12 (line 40): feed is NaN". Checks: finite target, feed > 0 and finite, tolerance > 0
// or +inf, known motion type (1, 2) and termination (0, 1), seq >= 1, |target| <= 1e6.
std::optional<std::string> validate(const firtp_lcm::block_t& message);

// "block seq N (line L)": how every error about one block message names it.
std::string describe(const firtp_lcm::block_t& message);

// Wall-clock microseconds since the epoch, LCM's utime convention.
std::int64_t now_utime();

// Valid message -> block (call validate first).
Block to_block(const firtp_lcm::block_t& message);

// Exactly-once, in-order acceptance of (program, seq); program ids only increase.
class SequenceChecker {
public:
    enum class Verdict {
        accept,        // seq == next_seq of the current program, or seq 1 of a new program when allowed
        repeated,      // seq < next_seq, or an older program: already accepted, must not run again
        gap,           // seq > next_seq: something was lost or reordered; the host resends from next_seq
        busy,          // a new program while the previous one still has blocks queued
    };
    // new_program_allowed: the component is idle (nothing queued), so a new program id may start.
    Verdict check(std::int64_t program, std::int64_t seq, bool new_program_allowed) const;
    void accepted(std::int64_t program, std::int64_t seq);  // after the block was really queued
    std::int64_t program() const { return program_; }
    std::int64_t next_seq() const { return next_seq_; }
    static const char* describe(Verdict verdict);

private:
    std::int64_t program_ = 0;
    std::int64_t next_seq_ = 1;
};

}  // namespace firtp::messages
