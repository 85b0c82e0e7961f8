// Host controller stub (not real-time): streams a program's blocks over LCM to the component with
// flow control and go-back-N resending (reading them as they go: memory for the blocks not yet
// acknowledged, not for the program), publishes operator controls (feed override, hold, abort)
// and watches FIRTP_STATUS until the program is done, failed, lost or aborted.
#pragma once

#include <firtp/gcode.hpp>
#include <firtp/trajectory.hpp>
#include <firtp_lcm/axis_state_t.hpp>
#include <firtp_lcm/event_t.hpp>
#include <firtp_lcm/status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace firtp::host {

using Clock = std::chrono::steady_clock;

struct HostOptions {
    int initial_window = 16;   // blocks sent before the first status arrives
    int max_burst = 64;        // blocks published per step() at most
    Clock::duration resend_timeout = std::chrono::milliseconds(500);  // no progress -> go back
    int max_resends = 10;      // go-backs to the same seq without progress before failing
    Clock::duration control_period = std::chrono::milliseconds(100);  // control_t republish
    Clock::duration status_timeout = std::chrono::seconds(3);         // no status -> lost
    double feed_scale = 1.0;       // initial feed override
    double max_feed_scale = 1.5;   // set_feed_scale clamps to 0 .. this
    bool record_axis_states = false;  // keep every FIRTP_AXIS_STATE message (axis_states())
    // Called with every intact FIRTP_AXIS_STATE message as it arrives (in step()), kept or not.
    std::function<void(const firtp_lcm::axis_state_t&)> on_axis_state;
    std::function<void(const firtp_lcm::event_t&)> on_event_reached;  // this program's, as motion reaches them
    std::int64_t program_id = 0;      // 0: microseconds of the system clock
    std::function<Clock::time_point()> clock;  // empty: Clock::now (tests inject a fake clock)
};

// A program as the host sends it: its blocks read in order as flow control lets them go, its
// events (a few a tool change, not a block) in memory.
struct ProgramFeed {
    std::size_t blocks = 0;            // how many a reader gives
    std::vector<ProgramEvent> events;  // in order of before_block
    // A new reader from the first block at each call: the host reads the program twice, once to
    // check every block before anything is sent, once to send them.
    std::function<std::unique_ptr<BlockPuller>()> read;
};
// A program in memory as a feed.
ProgramFeed feed_of(std::shared_ptr<const Program> program);

enum class Result {
    running,
    done,     // every block acknowledged and executed (queue empty, component idle)
    failed,   // the component reported an error, or a block was never accepted (error() says why)
    lost,     // no status for status_timeout
    aborted,  // abort() and the component confirmed it stopped with an empty queue
};
const char* to_string(Result result);

// status_t::state as a word ("idle", "moving", ...); "waiting" for -1 (no status yet).
const char* state_name(int state);

struct Progress {
    std::size_t blocks = 0;        // in the program, with its events (one seq each)
    std::size_t sent = 0;          // highest seq published so far
    std::size_t acknowledged = 0;  // accepted by the component
    std::size_t executed = 0;      // accepted and no longer queued
    int line = 0;                  // G-code line moving now (status current_line)
    int state = -1;                // status_t state, -1 before the first status of the run
    double feed_in_effect = 1.0;   // status feed_scale
    double feed_request = 1.0;     // what this host asks for
    bool hold = false;
    bool abort = false;
};

struct Statistics {
    std::int64_t blocks_published = 0;  // including resends
    std::int64_t events_published = 0;  // program events (event_t), likewise
    std::int64_t events_reached = 0;    // of this program's events: reached by the motion (FIRTP_EVENT_REACHED)
    std::int64_t go_backs = 0;          // go-back-N resends
    std::int64_t rejected = 0;          // blocks the component refused while this host ran
    std::int64_t corrupted_refused = 0; // of those and of the controls: refused as corrupted (bad crc)
    std::int64_t corrupted_dropped = 0; // statuses and axis states dropped here as corrupted (bad crc)
    std::int64_t statuses = 0;
    std::int64_t controls = 0;          // control_t messages published
    std::int64_t axis_states = 0;       // FIRTP_AXIS_STATE messages received
    std::int64_t axis_states_lost = 0;  // gaps in their seq
};

class Host {
public:
    // Subscribes to FIRTP_STATUS and FIRTP_AXIS_STATE on `lcm` (messages whose crc does not match
    // are dropped, as if lost); every message it publishes is sealed. Blocks that fail
    // messages::validate make the host fail at once, before anything is sent.
    Host(lcm::LCM& lcm, const ProgramFeed& program, HostOptions options = {});
    Host(lcm::LCM& lcm, const Program& program, HostOptions options = {});  // a copy of it
    ~Host();
    Host(const Host&) = delete;
    Host& operator=(const Host&) = delete;

    // Handles pending messages, publishes what flow control allows and the periodic control.
    // Never blocks.
    Result step();
    // step() until a final result, a stop request or the deadline (options' clock); waits on LCM
    // for at most 10 ms between steps. Returns result() (running when stopped early).
    Result run(std::stop_token stop = {}, std::optional<Clock::time_point> deadline = {});

    void set_feed_scale(double scale);  // clamped to 0 .. max_feed_scale
    void hold(bool on);
    void abort();                       // stop sending; aborted once the component is idle and empty

    Result result() const;
    const std::string& error() const;   // why failed / lost; empty otherwise
    Progress progress() const;
    Statistics statistics() const;
    std::int64_t program_id() const;
    double max_feed_scale() const;
    std::string axis_state_gap_text() const;  // "" or "N axis-state messages lost (first after seq S)"
    const std::vector<firtp_lcm::axis_state_t>& axis_states() const;  // when recording

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace firtp::host
