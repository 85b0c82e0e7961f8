// Axis limits for the limit tests, and how close a sampled trajectory comes to them.
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace firtp::test {

// X Y Z with the same limits.
inline MachineLimits uniform_limits(double v, double a, double j) {
    MachineLimits l;
    l.axes = 3;
    for (int i = 0; i < 3; ++i) l.axis[i] = {v, a, j};
    return l;
}

// Largest |value| / limit over every sample and axis (the chain's values at the samples): velocity
// and acceleration, and jerk when `with_jerk`.
inline double worst_ratio(const std::vector<AxisState>& samples, const MachineLimits& l, bool with_jerk = true) {
    double worst = 0.0;
    for (const AxisState& s : samples)
        for (int a = 0; a < l.axes; ++a) {
            worst = std::max(worst, std::abs(s.velocity[a]) / l.axis[a].max_velocity);
            worst = std::max(worst, std::abs(s.acceleration[a]) / l.axis[a].max_acceleration);
            if (with_jerk) worst = std::max(worst, std::abs(s.jerk[a]) / l.axis[a].max_jerk);
        }
    return worst;
}

}  // namespace firtp::test
