// Recorded against replayed axis states. Motion is compared state by state; where both are at
// rest they must rest at the same place, and the next motion is aligned on its first moving state
// (when a block arrives is the transport's timing, not the component's behaviour).
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
    std::string what;          // "position", "velocity", "acceleration", "line", "motion"
    int axis = -1;             // for the per-axis quantities
    double recorded_value = 0.0, replayed_value = 0.0;
};

struct Comparison {
    std::size_t compared = 0;    // recorded states matched to a replayed one
    double largest = 0.0;        // largest |difference| of position, velocity or acceleration (absolute)
    std::optional<StateDifference> first;  // empty: equal
};

// Two values are equal when |replayed - recorded| <= tolerance * max(1, |recorded|) (0: bit for
// bit). `axes` of the 9 are compared.
Comparison compare_states(const std::vector<firtp_lcm::axis_state_t>& recorded,
                          const std::vector<firtp_lcm::axis_state_t>& replayed, int axes, double tolerance);

}  // namespace firtp::cli
