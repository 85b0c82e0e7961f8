// Whether a sampled trajectory keeps the axis limits, at the samples and in the finite differences
// of their positions (what a drive computes).
#pragma once

#include "random_machine.hpp"

#include <firtp/measure.hpp>
#include <firtp/parameters.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace firtp::test {

// The first value beyond a limit, in words ("" if none): |v|, |a| and (with `jerk`, on axes that
// limit it) |j| at every sample, 1e-6 above the limit at most; then the same in `m`'s finite
// differences, beyond their rounding noise (difference_noise).
inline std::string beyond_limits(const std::vector<AxisState>& samples, const Measured& m, const PlannerParameters& p,
                                 bool jerk = true) {
    const double slack = 1.0 + 1e-6;
    std::ostringstream why;
    for (int a = 0; a < p.limits.axes; ++a) {
        const AxisLimits& l = p.limits.axis[a];
        const bool with_jerk = jerk && l.max_jerk > 0.0;
        for (const AxisState& s : samples) {
            if (std::abs(s.velocity[a]) > l.max_velocity * slack) why << "axis " << a << " v " << s.velocity[a];
            else if (std::abs(s.acceleration[a]) > l.max_acceleration * slack) why << "axis " << a << " a " << s.acceleration[a];
            else if (with_jerk && std::abs(s.jerk[a]) > l.max_jerk * slack) why << "axis " << a << " j " << s.jerk[a];
            else continue;
            why << " at " << s.time << " s";
            return why.str();
        }
        if (m.max_velocity[a] > l.max_velocity * slack) why << "axis " << a << " v " << m.max_velocity[a];
        else if (m.max_acceleration[a] > l.max_acceleration * slack + difference_noise(samples, a, p.period, 2))
            why << "axis " << a << " a " << m.max_acceleration[a];
        else if (with_jerk && m.max_jerk[a] > l.max_jerk * slack + difference_noise(samples, a, p.period, 3))
            why << "axis " << a << " j " << m.max_jerk[a];
        else continue;
        why << " in the finite differences";
        return why.str();
    }
    return "";
}

}  // namespace firtp::test
