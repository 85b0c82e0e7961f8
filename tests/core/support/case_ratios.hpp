// How close one planned random case comes to its limits and tolerances, measured on the samples
// (firtp_cliffs --check; the randomized suites assert the same quantities sample by sample).
#pragma once

#include "random_machine.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace firtp::test {

struct CaseRatios {
    double corner = 0.0;  // largest corner error / tolerance (blended turns)
    double velocity = 0.0, acceleration = 0.0, jerk = 0.0;  // of the limits: samples and differences
                                                            // (per period and per ms, less rounding noise)
    bool end_exact = false, at_rest = false, finite = false;
    bool within() const {
        constexpr double slack = 1.0 + 1e-6;
        return finite && end_exact && at_rest && corner <= 1.0 && velocity <= slack && acceleration <= slack && jerk <= slack;
    }
};

inline CaseRatios case_ratios(const PlannerParameters& p, const std::vector<Block>& blocks, const Trajectory& t) {
    CaseRatios r;
    std::vector<AxisVector> points{AxisVector::Zero()};
    std::vector<const Block*> ending;
    for (const Block& b : blocks)
        if ((b.target - points.back()).norm() >= min_block_length) points.push_back(b.target), ending.push_back(&b);
    const Measured m = measure(t.samples, points, p.period);
    r.finite = m.finite;
    r.end_exact = !blocks.empty() && m.end_position == blocks.back().target;
    r.at_rest = !t.samples.empty() && t.samples.back().velocity == AxisVector::Zero();
    for (std::size_t i = 0; i < m.corner_errors.size() && i + 2 < points.size(); ++i) {
        const Block& b = *ending[i];
        const AxisVector in = points[i + 1] - points[i], out = points[i + 2] - points[i + 1];
        if (b.termination != Termination::blend || in.normalized().dot(out.normalized()) > 1.0 - 1e-12) continue;
        r.corner = std::max(r.corner, m.corner_errors[i] / b.tolerance);
    }
    const auto step = static_cast<std::size_t>(std::max(1L, std::lround(0.001 / p.period)));
    std::vector<AxisState> per_ms;
    for (std::size_t k = 0; k < t.samples.size(); k += step) per_ms.push_back(t.samples[k]);
    const Measured ms = measure(per_ms, points, static_cast<double>(step) * p.period);
    for (int a = 0; a < p.limits.axes; ++a) {
        const AxisLimits& l = p.limits.axis[a];
        for (const AxisState& s : t.samples) {
            r.velocity = std::max(r.velocity, std::abs(s.velocity[a]) / l.max_velocity);
            r.acceleration = std::max(r.acceleration, std::abs(s.acceleration[a]) / l.max_acceleration);
            if (l.max_jerk > 0.0) r.jerk = std::max(r.jerk, std::abs(s.jerk[a]) / l.max_jerk);
        }
        for (const Measured* d : {&m, &ms}) {
            const double period = d == &m ? p.period : static_cast<double>(step) * p.period;
            r.velocity = std::max(r.velocity, d->max_velocity[a] / l.max_velocity);
            r.acceleration = std::max(r.acceleration, (d->max_acceleration[a] - difference_noise(t.samples, a, period, 2)) / l.max_acceleration);
            if (l.max_jerk > 0.0) r.jerk = std::max(r.jerk, (d->max_jerk[a] - difference_noise(t.samples, a, period, 3)) / l.max_jerk);
        }
    }
    return r;
}

}  // namespace firtp::test
