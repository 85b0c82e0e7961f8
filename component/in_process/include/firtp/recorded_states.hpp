// The trajectory as it travelled over LCM (FIRTP_AXIS_STATE), laid out as `firtp plan` samples it.
#pragma once

#include <firtp/types.hpp>
#include <firtp_lcm/axis_state_t.hpp>

#include <vector>

namespace firtp {

// First sample: the period the first block started in (t = 0, at the start point); last sample:
// the first period at rest after the motion. Jerk is not sent: it is the first difference of the
// received accelerations. Throws std::runtime_error when no block ever moved.
std::vector<AxisState> samples_from_axis_states(const std::vector<firtp_lcm::axis_state_t>& states, double period);

}  // namespace firtp
