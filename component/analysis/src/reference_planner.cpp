#include <firtp/reference_planner.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace firtp {
namespace {

constexpr double direction_floor = 1e-12;  // |u_axis| below this: the axis does not move

struct Phases {
    double tj = 0.0;  // each jerk phase
    double ta = 0.0;  // constant acceleration
    double peak_acceleration = 0.0;
    double accelerate() const { return 2.0 * tj + ta; }
};

Phases phases(double vp, double a, double j) {
    Phases p;
    if (!(j > 0.0) || !std::isfinite(j)) {
        p.ta = vp / a;
        p.peak_acceleration = a;
    } else if (vp * j >= a * a) {
        p.tj = a / j;
        p.ta = vp / a - a / j;
        p.peak_acceleration = a;
    } else {
        p.tj = std::sqrt(vp / j);
        p.peak_acceleration = j * p.tj;
    }
    return p;
}

}  // namespace

SCurve::SCurve(double length, double max_velocity, double max_acceleration, double max_jerk) {
    if (!(length >= 0.0 && max_velocity > 0.0 && max_acceleration > 0.0))
        throw std::invalid_argument("SCurve: length >= 0, velocity and acceleration limits > 0");
    if (length == 0.0) return;
    // Accelerating to vp and back takes vp * accelerate(vp) of the length; bisect vp when the
    // block is too short to cruise at the limit.
    double vp = max_velocity;
    Phases p = phases(vp, max_acceleration, max_jerk);
    if (vp * p.accelerate() > length) {
        double lo = 0.0, hi = max_velocity;
        for (int i = 0; i < 200 && hi - lo > 1e-15 * max_velocity; ++i) {
            const double mid = 0.5 * (lo + hi);
            (mid * phases(mid, max_acceleration, max_jerk).accelerate() > length ? hi : lo) = mid;
        }
        vp = lo;
        p = phases(vp, max_acceleration, max_jerk);
    }
    const double tv = std::max(0.0, (length - vp * p.accelerate()) / vp);
    const double jerk = p.tj > 0.0 ? p.peak_acceleration / p.tj : 0.0;
    const double ap = p.peak_acceleration;
    const double lengths[7] = {p.tj, p.ta, p.tj, tv, p.tj, p.ta, p.tj};
    const double jerks[7] = {jerk, 0.0, -jerk, 0.0, -jerk, 0.0, jerk};
    const double start_acceleration[7] = {0.0, ap, ap, 0.0, 0.0, -ap, -ap};
    State state;
    double t = 0.0;
    for (std::size_t i = 0; i < 7; ++i) {
        state.a = start_acceleration[i];
        state.j = jerks[i];
        segments_[i] = {t, lengths[i], jerks[i], state};
        const double dt = lengths[i];
        state.s += state.v * dt + state.a * dt * dt / 2.0 + state.j * dt * dt * dt / 6.0;
        state.v += state.a * dt + state.j * dt * dt / 2.0;
        t += dt;
    }
    duration_ = t;
    peak_velocity_ = vp;
}

SCurve::State SCurve::at(double t) const {
    if (t >= duration_) {
        State end;
        const Segment& last = segments_.back();
        const double dt = last.length;
        end.s = last.state.s + last.state.v * dt + last.state.a * dt * dt / 2.0 + last.jerk * dt * dt * dt / 6.0;
        return end;
    }
    t = std::max(t, 0.0);
    std::size_t i = 0;
    while (i + 1 < segments_.size() && t >= segments_[i + 1].start) ++i;
    const Segment& seg = segments_[i];
    const double dt = t - seg.start;
    State s;
    s.j = seg.jerk;
    s.a = seg.state.a + seg.jerk * dt;
    s.v = seg.state.v + seg.state.a * dt + seg.jerk * dt * dt / 2.0;
    s.s = seg.state.s + seg.state.v * dt + seg.state.a * dt * dt / 2.0 + seg.jerk * dt * dt * dt / 6.0;
    return s;
}

std::vector<AxisState> plan_exact_stop_scurves(const MachineLimits& limits, double period, const AxisVector& start,
                                               std::span<const Block> blocks) {
    if (!(period > 0.0)) throw std::invalid_argument("the servo period must be positive");
    std::vector<AxisState> samples;
    AxisVector here = start;
    std::size_t k = 0;
    const auto time_of = [&](std::size_t index) { return static_cast<double>(index) * period; };
    for (const Block& block : blocks) {
        const AxisVector delta = block.target - here;
        const double length = delta.norm();
        if (length < min_block_length) continue;
        if (!(block.feed > 0.0) || !std::isfinite(block.feed))
            throw std::invalid_argument("line " + std::to_string(block.line) + ": the feed must be positive");
        const AxisVector u = delta / length;
        double v = block.feed, a = std::numeric_limits<double>::infinity(), j = std::numeric_limits<double>::infinity();
        for (int i = 0; i < limits.axes; ++i) {
            const double share = std::abs(u[i]);
            if (share < direction_floor) continue;
            const AxisLimits& l = limits.axis[i];
            if (l.max_velocity > 0.0) v = std::min(v, l.max_velocity / share);
            if (!(l.max_acceleration > 0.0))
                throw std::invalid_argument("line " + std::to_string(block.line) + ": axis " +
                                            axis_letters[i] +
                                            " moves without an acceleration limit");
            a = std::min(a, l.max_acceleration / share);
            if (l.max_jerk > 0.0) j = std::min(j, l.max_jerk / share);
        }
        const double xyz = u.head<3>().norm();
        if (limits.max_linear_velocity > 0.0 && xyz > direction_floor) v = std::min(v, limits.max_linear_velocity / xyz);
        const SCurve curve(length, v, a, j);
        const double t0 = time_of(k);
        for (; time_of(k) - t0 < curve.duration(); ++k) {
            const SCurve::State s = curve.at(time_of(k) - t0);
            AxisState state;
            state.time = time_of(k);
            state.position = here + u * s.s;
            state.velocity = u * s.v;
            state.acceleration = u * s.a;
            state.jerk = u * s.j;
            state.line = block.line;
            samples.push_back(state);
        }
        here = block.target;
    }
    AxisState rest;
    rest.time = time_of(k);
    rest.position = here;
    rest.line = samples.empty() ? 0 : samples.back().line;
    samples.push_back(rest);
    return samples;
}

}  // namespace firtp
