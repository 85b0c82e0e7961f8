// When `firtp replay` gives the component each logged input. Every axis state says which blocks the
// recorded component had taken by the end of its period (axis_state_t program, next_seq): a block
// it took goes in once, just before the period that took it, so the replay takes the same blocks
// in the same periods. Controls, and blocks it never took (refused ones), go in as logged: before
// the period of the first axis state logged after them. Resent copies of taken blocks are left out.
#pragma once

#include "replay_log.hpp"

#include <vector>

namespace firtp::cli {

struct FeedSchedule {
    // before[i]: the inputs to publish before the period of run.states[i]; before[states.size()]:
    // those logged after the last state.
    std::vector<std::vector<const LoggedEvent*>> before;
    std::size_t placed_by_state = 0;  // blocks placed by the states' program and next_seq
};

// Throws std::runtime_error naming the axis state when it says a block was taken that the log does
// not hold (a recorder started after the host).
FeedSchedule feed_schedule(const LoggedRun& run);

}  // namespace firtp::cli
