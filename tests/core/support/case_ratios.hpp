// One planned random case measured on its samples (measure_case: the randomized suites assert on
// it sample by sample), and how close it comes to its limits and tolerances (case_ratios:
// firtp_cliffs --check).
#pragma once

#include "random_machine.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace firtp::test {

// One planned case measured on its samples: per period, and every 1 ms as a drive reading the
// positions at that rate would; the programmed points, and the block ending at each interior one.
struct MeasuredCase {
    std::vector<AxisVector> points;    // the start, then the end of every block that moves
    std::vector<const Block*> ending;  // ending[i]: the block that ends at points[i + 1]
    Measured per_period, per_ms;
    double period = 0.0, ms_period = 0.0;  // the periods of their differences
    // Whether the junction at points[i + 1] is a blended turn, whose error its tolerance bounds.
    bool blended_turn(std::size_t i) const {
        const AxisVector in = points[i + 1] - points[i], out = points[i + 2] - points[i + 1];
        return ending[i]->termination == Termination::blend && in.normalized().dot(out.normalized()) <= 1.0 - 1e-12;
    }
};

inline MeasuredCase measure_case(const PlannerParameters& p, const std::vector<Block>& blocks, const Trajectory& t,
                                 const AxisVector& start = AxisVector::Zero()) {
    MeasuredCase c;
    c.points.push_back(start);
    for (const Block& b : blocks)
        if ((b.target - c.points.back()).norm() >= min_block_length) c.points.push_back(b.target), c.ending.push_back(&b);
    c.period = p.period;
    c.per_period = measure(t.samples, c.points, p.period);
    const auto step = static_cast<std::size_t>(std::max(1L, std::lround(0.001 / p.period)));
    std::vector<AxisState> per_ms;
    for (std::size_t k = 0; k < t.samples.size(); k += step) per_ms.push_back(t.samples[k]);
    c.ms_period = static_cast<double>(step) * p.period;
    c.per_ms = measure(per_ms, c.points, c.ms_period);
    return c;
}

struct CaseRatios {
    double corner = 0.0;  // largest corner error / tolerance (blended turns)
    double velocity = 0.0, acceleration = 0.0, jerk = 0.0;  // of the limits: samples and differences
                                                            // (per period and per ms, less rounding noise)
    bool end_exact = false, at_rest = false, finite = false;
    bool within() const {
        constexpr double slack = 1.0 + 1e-6;
        return finite && end_exact && at_rest && corner <= 1.0 && velocity <= slack && acceleration <= slack && jerk <= slack;
    }
    // The worst of this and r, ratio by ratio (over many cases).
    void take_worst(const CaseRatios& r) {
        corner = std::max(corner, r.corner);
        velocity = std::max(velocity, r.velocity);
        acceleration = std::max(acceleration, r.acceleration);
        jerk = std::max(jerk, r.jerk);
    }
};

inline CaseRatios case_ratios(const PlannerParameters& p, const std::vector<Block>& blocks, const Trajectory& t,
                              const AxisVector& start = AxisVector::Zero()) {
    CaseRatios r;
    const MeasuredCase c = measure_case(p, blocks, t, start);
    r.finite = c.per_period.finite;
    r.end_exact = !blocks.empty() && c.per_period.end_position == blocks.back().target;
    r.at_rest = !t.samples.empty() && t.samples.back().velocity == AxisVector::Zero();
    for (std::size_t i = 0; i < c.per_period.corner_errors.size() && i + 2 < c.points.size(); ++i)
        if (c.blended_turn(i)) r.corner = std::max(r.corner, c.per_period.corner_errors[i] / c.ending[i]->tolerance);
    for (int a = 0; a < p.limits.axes; ++a) {
        const AxisLimits& l = p.limits.axis[a];
        for (const AxisState& s : t.samples) {
            r.velocity = std::max(r.velocity, std::abs(s.velocity[a]) / l.max_velocity);
            r.acceleration = std::max(r.acceleration, std::abs(s.acceleration[a]) / l.max_acceleration);
            if (l.max_jerk > 0.0) r.jerk = std::max(r.jerk, std::abs(s.jerk[a]) / l.max_jerk);
        }
        for (const auto& [d, period] : {std::pair{&c.per_period, c.period}, std::pair{&c.per_ms, c.ms_period}}) {
            r.velocity = std::max(r.velocity, d->max_velocity[a] / l.max_velocity);
            r.acceleration = std::max(r.acceleration, (d->max_acceleration[a] - difference_noise(t.samples, a, period, 2)) / l.max_acceleration);
            if (l.max_jerk > 0.0) r.jerk = std::max(r.jerk, (d->max_jerk[a] - difference_noise(t.samples, a, period, 3)) / l.max_jerk);
        }
    }
    return r;
}

}  // namespace firtp::test
