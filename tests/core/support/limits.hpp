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

// firtp plan's built-in machine, X Y Z at 300 mm/s, 5000 mm/s^2, 1e5 mm/s^3, a 1 ms period, no
// feed override above 100 %.
inline PlannerParameters builtin_machine() {
    PlannerParameters p;
    p.period = 0.001;
    p.max_rate = 1.0;
    p.limits = uniform_limits(300.0, 5000.0, 1e5);
    return p;
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
