// Recorded against replayed axis states, one to one: the replay takes every block in the period
// the recording took it (replay_feed.hpp), so state i of the one is state i of the other.
#pragma once

#include <firtp_lcm/axis_state_t.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace firtp::cli {

struct StateDifference {
    std::size_t recorded = 0;  // index into the recorded states (the replayed one: `replayed`)
    std::size_t replayed = 0;
    std::string what;          // "position", "velocity", "acceleration", "line", "next_seq", "control_session",
                               // "control_seq", "missing"
    int axis = -1;             // for the per-axis quantities
    double recorded_value = 0.0, replayed_value = 0.0;
};

struct Comparison {
    std::size_t compared = 0;    // recorded states equal to their replayed one
    double largest = 0.0;        // largest |difference| of position, velocity or acceleration (absolute)
    std::optional<StateDifference> first;  // empty: equal
};

// Two values are equal when |replayed - recorded| <= tolerance * max(1, |recorded|) (0: bit for
// bit). `axes` of the 9 are compared, and the line, next_seq and the control applied; "missing": the replay
// has fewer states.
Comparison compare_states(const std::vector<firtp_lcm::axis_state_t>& recorded,
                          const std::vector<firtp_lcm::axis_state_t>& replayed, int axes, double tolerance);

}  // namespace firtp::cli
