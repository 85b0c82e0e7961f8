// When `firtp replay` gives the component each logged input. Every axis state says which blocks the
// recorded component had taken by the end of its period (axis_state_t program, next_seq) and which
// operator control it applied in the period (control_session, control_seq): a block it took goes
// in once, just before the period that took it, and so does that control, with the controls of its
// session before it not fed yet (taken by the bridge, superseded before a period read them), so the
// replay takes the same blocks and controls in the same periods. Inputs never taken (refused
// blocks, controls older than the one in effect, or logged after the last state) go in as logged:
// before the period of the first axis state logged after them. Resent copies of taken blocks and
// repeated copies of taken controls are left out.
#pragma once

#include "replay_log.hpp"

#include <vector>

namespace firtp::cli {

struct FeedSchedule {
    // before[i]: the inputs to publish before the period of run.states[i]; before[states.size()]:
    // those logged after the last state.
    std::vector<std::vector<const LoggedEvent*>> before;
    std::size_t placed_by_state = 0;           // blocks (and events) placed by the states' program and next_seq
    std::size_t controls_placed_by_state = 0;  // controls placed by the states' control_session and control_seq
};

// Throws std::runtime_error naming the axis state (seq, log event) when it says a block or control
// was taken that the log does not hold (a recorder started after the host).
FeedSchedule feed_schedule(const LoggedRun& run);

}  // namespace firtp::cli
