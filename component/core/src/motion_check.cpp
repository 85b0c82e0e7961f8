#include <firtp/motion_check.hpp>

#include <firtp/junction.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace firtp {

namespace {

constexpr double slack = 1.0 + 1e-9;
// A second stage this much shorter than the first moves nothing (a junction step of almost no
// speed change has a box of ~1e-17 s): checked as one stage, whose jump is then exact.
constexpr double negligible_stage = 1e-9;
// Knots this close are one: the steps that meet at a junction start on sums that round differently.
constexpr double same_knot = 1e-12;

// A knot of the sum: the jerk changes by `jerk`, the acceleration by `acceleration` (one-stage
// kernels), the velocity by `velocity` (sharp steps).
using Knot = LimitSweep::Knot;

// The two stages that bound a kernel's derivatives (the first two of a chain).
void stages(const Kernel& k, double& a, double& b) {
    if (k.chain != nullptr) {
        const FilterTimes& f = k.chain->filters();
        a = f.T[0];
        b = f.stages > 1 ? f.T[1] : 0.0;
    } else {
        a = k.a;
        b = k.b;
    }
}

// The knots of one step: those after `from` and up to `to` are appended at knots[n...] (returns
// the new n); those before it are summed into the state at `from` (v, a, j). Both from the same
// knot times, so a knot that rounds onto `from` is counted exactly once.
std::size_t add_knots(std::vector<Knot>& knots, std::size_t n, const AxisVector& dv, double start, const Kernel& k,
                      double from, double to, AxisVector& v, AxisVector& a, AxisVector& j) {
    double ta = 0.0, tb = 0.0;
    stages(k, ta, tb);
    // At `from` the state holds every knot before it and those at it but the kernel's start (the
    // response is 0 there, its right-hand derivatives are not).
    // A jump of `value` in the derivative of order `order` (1 velocity, 2 acceleration, 3 jerk).
    auto add = [&](double t, const AxisVector& value, int order) {
        if (t > from || (t == from && t == start)) {
            if (t <= to && n < knots.size()) knots[n++] = {t, value, order};
            return;
        }
        const double dt = from - t;
        if (order == 3) j += value, a += value * dt, v += value * (0.5 * dt * dt);
        else if (order == 2) a += value, v += value * dt;
        else v += value;
    };
    if (ta <= 0.0) {
        add(start, dv, 1);
    } else if (tb <= negligible_stage * ta) {  // (a stage of 1e-17 s would give jerks of 1e21 to cancel)
        add(start, dv / ta, 2);
        add(start + ta, -dv / ta, 2);
    } else {
        const AxisVector jk = dv / (ta * tb);
        add(start, jk, 3);
        add(start + tb, -jk, 3);
        add(start + ta, -jk, 3);
        add(start + ta + tb, jk, 3);
    }
    return n;
}

struct Checker {
    const MachineLimits& limits;
    LimitCheck result;

    bool over(double value, double limit, double t, int axis, int derivative) {
        if (limit > 0.0 && std::abs(value) > limit * slack && result.ok) {
            result = {false, t, axis, derivative, value};
            return true;
        }
        return false;
    }
    void state(double t, const AxisVector& v, const AxisVector& a) {
        for (int i = 0; i < limits.axes; ++i) {
            over(v[i], limits.axis[i].max_velocity, t, i, 1);
            over(a[i], limits.axis[i].max_acceleration, t, i, 2);
        }
    }
};

}  // namespace

LimitSweep::LimitSweep(std::size_t max_legs) : knots_(max_legs * 8) {}

LimitCheck LimitSweep::check(std::span<const TimedLeg> legs, double from, double to, const MachineLimits& limits,
                             double period) {
    std::vector<Knot>& knots = knots_;
    std::size_t n = 0;
    AxisVector v = AxisVector::Zero(), a = AxisVector::Zero(), j = AxisVector::Zero();
    for (const TimedLeg& leg : legs) {
        if (!(leg.tv > 0.0)) continue;  // no time, no motion
        const AxisVector dv = leg.delta / leg.tv;
        const double starts[2] = {leg.rise, leg.rise + leg.fall};
        const Kernel* kernels[2] = {&leg.rising, &leg.falling};
        for (int e = 0; e < 2; ++e) {
            const AxisVector step = e == 0 ? dv : AxisVector(-dv);
            n = add_knots(knots, n, step, starts[e], *kernels[e], from, to, v, a, j);
        }
    }
    std::sort(knots.begin(), knots.begin() + static_cast<std::ptrdiff_t>(n),
              [](const Knot& x, const Knot& y) { return x.t < y.t; });
    Checker c{limits, {}};
    c.state(from, v, a);
    double t = from;
    for (std::size_t k = 0; k <= n; ++k) {
        const double next = k < n ? knots[k].t : to;
        const double dt = next - t;
        if (dt > 0.0) {
            // Knots that coincide are computed from sums that round differently: an interval of a
            // nanosecond between them has no jerk that moves anything.
            const bool real = dt > 1e-9;
            for (int i = 0; i < limits.axes; ++i) {
                if (real) c.over(j[i], limits.axis[i].max_jerk, t, i, 3);
                // A velocity extremum inside the interval, where the acceleration crosses zero.
                if (j[i] != 0.0) {
                    const double tz = -a[i] / j[i];
                    if (tz > 0.0 && tz < dt) c.over(v[i] + a[i] * tz + 0.5 * j[i] * tz * tz, limits.axis[i].max_velocity, t + tz, i, 1);
                }
            }
            v += a * dt + j * (0.5 * dt * dt);
            a += j * dt;
            t = next;
            c.state(t, v, a);
        }
        if (k == n) break;
        // Every knot at this time at once: the jumps of two legs meeting at a junction cancel.
        AxisVector jump = AxisVector::Zero();
        bool jumps = false;
        for (; k < n && knots[k].t <= t + same_knot; ++k) {
            const Knot& knot = knots[k];
            if (knot.order == 2) jump += knot.value, jumps = true;
            (knot.order == 3 ? j : knot.order == 2 ? a : v) += knot.value;
        }
        --k;
        if (jumps)
            for (int i = 0; i < limits.axes; ++i)  // a jump in acceleration, as the samples' differences see it
                if (jump[i] != 0.0) c.over(jump[i] / period, limits.axis[i].max_jerk, t, i, 3);
        c.state(t, v, a);
        if (!c.result.ok) break;
    }
    return c.result;
}

void index_legs(std::span<TimedLeg> legs) {
    double reach = 0.0;
    int axes = 0;
    AxisVector at = AxisVector::Zero();
    for (TimedLeg& leg : legs) {
        leg.before = at;
        at += leg.delta;
        leg.rise_centre = leg.rise + 0.5 * leg.rising.width();
        leg.fall_centre = leg.rise + leg.fall + 0.5 * leg.falling.width();
        reach = std::max({reach, 0.5 * leg.rising.width(), 0.5 * leg.falling.width()});
        for (int i = max_axes; i > axes; --i)
            if (leg.delta[i - 1] != 0.0) axes = i;
    }
    for (TimedLeg& leg : legs) leg.reach = reach, leg.axes = axes;
}

namespace {

// relative_state's sum; with Derivatives false only the position (the same arithmetic).
template <bool Derivatives>
void sum_legs(std::span<const TimedLeg> legs, std::size_t corner, double t, AxisState& s) {
    if (legs.empty()) return;
    std::size_t lo = 0, hi = legs.size();  // legs [lo, hi) may move at t
    const double reach = legs.front().reach;
    if (reach > 0.0) {
        // The margin covers the rounding of the centres against the kernels' own arithmetic.
        const double margin = 1e-9 + 1e-12 * std::abs(t);
        lo = static_cast<std::size_t>(std::partition_point(legs.begin(), legs.end(), [&](const TimedLeg& l) {
                                          return l.fall_centre + reach < t - margin;
                                      }) - legs.begin());
        hi = static_cast<std::size_t>(std::partition_point(legs.begin() + static_cast<std::ptrdiff_t>(lo), legs.end(),
                                                           [&](const TimedLeg& l) { return l.rise_centre - reach <= t + margin; }) -
                                      legs.begin());
        // Before lo: ended (S = 1); from hi on: not begun (S = 0). Relative to the corner point,
        // the legs' path from the corner to the first moving leg, or back from the first still.
        const AxisVector& corner_end = corner + 1 < legs.size() ? legs[corner + 1].before : AxisVector(legs[corner].before + legs[corner].delta);
        const AxisVector done = lo < legs.size() ? legs[lo].before : AxisVector(legs.back().before + legs.back().delta);
        const AxisVector waiting = hi < legs.size() ? legs[hi].before : AxisVector(legs.back().before + legs.back().delta);
        if (lo > corner + 1) s.position += done - corner_end;     // legs after the corner that ended
        if (hi <= corner) s.position -= corner_end - waiting;     // legs up to the corner not begun
    }
    const int axes = legs.front().axes;  // the other axes' sums stay 0
    for (std::size_t k = lo; k < hi; ++k) {
        const TimedLeg& leg = legs[k];
        if (!(leg.tv > 0.0)) continue;
        const double sign = k <= corner ? 1.0 : 0.0;
        if constexpr (Derivatives) {
            const StepSample up = leg.rising.step(t - leg.rise);
            const StepSample down = leg.falling.step(t - leg.rise - leg.fall);
            const double p = (up.position - down.position) / leg.tv - sign;
            const double v = (up.velocity - down.velocity) / leg.tv;
            const double a = (up.acceleration - down.acceleration) / leg.tv;
            const double j = (up.jerk - down.jerk) / leg.tv;
            for (int i = 0; i < axes; ++i) {
                const double d = leg.delta[i];
                s.position[i] += d * p;
                s.velocity[i] += d * v;
                s.acceleration[i] += d * a;
                s.jerk[i] += d * j;
            }
        } else {
            const double p = (leg.rising.step_position(t - leg.rise) - leg.falling.step_position(t - leg.rise - leg.fall)) / leg.tv - sign;
            for (int i = 0; i < axes; ++i) s.position[i] += leg.delta[i] * p;
        }
    }
}

}  // namespace

AxisState relative_state(std::span<const TimedLeg> legs, std::size_t corner, double t) {
    AxisState s;
    s.time = t;
    sum_legs<true>(legs, corner, t, s);
    return s;
}

AxisVector relative_position(std::span<const TimedLeg> legs, std::size_t corner, double t) {
    AxisState s;
    sum_legs<false>(legs, corner, t, s);
    return s.position;
}

namespace {

// Distance from the origin to the chord from p to q.
double chord_distance(const AxisVector& p, const AxisVector& q) {
    const AxisVector d = q - p;
    const double dd = d.squaredNorm();
    const double u = dd > 0.0 ? std::clamp(-p.dot(d) / dd, 0.0, 1.0) : 0.0;
    return (p + u * d).norm();
}

}  // namespace

Approach closest_approach(std::span<const TimedLeg> legs, std::size_t corner, double guess, double period, int phases) {
    Approach best{HUGE_VAL, guess, HUGE_VAL, HUGE_VAL};
    double t = guess;
    for (int i = 0; i < 6; ++i) {
        const AxisState s = relative_state(legs, corner, t);
        const double d = s.position.norm();
        if (d < best.smooth) best.smooth = d, best.time = t;
        // Newton on (x - P) . v = 0, the derivative of |x - P|^2 / 2.
        const double f = s.position.dot(s.velocity);
        const double df = s.velocity.squaredNorm() + s.position.dot(s.acceleration);
        if (!(df > 0.0)) break;
        const double step = std::clamp(-f / df, -4.0 * period, 4.0 * period);
        if (std::abs(step) < 1e-12) break;
        t += step;
    }
    // The drives go straight from sample to sample (t = (k + phase) period): the chords around
    // the approach, for each phase the worst.
    best.sampled = 0.0;
    for (int f = 0; f < std::max(phases, 1); ++f) {
        const double phase = static_cast<double>(f) / std::max(phases, 1);
        const double k0 = std::floor(best.time / period - phase);
        double nearest = HUGE_VAL;
        AxisVector previous = relative_position(legs, corner, (k0 - sampled_chords + phase) * period);
        for (double k = k0 - sampled_chords + 1; k <= k0 + sampled_chords + 1; ++k) {
            const AxisVector next = relative_position(legs, corner, (k + phase) * period);
            nearest = std::min(nearest, chord_distance(previous, next));
            previous = next;
        }
        best.sampled = std::max(best.sampled, nearest);
    }
    best.distance = std::max(best.smooth, best.sampled);
    return best;
}

double contour_error(std::span<const TimedLeg> legs, std::size_t corner, double at, double width, double period) {
    const double from = at - 0.5 * width - period, to = at + 0.5 * width + period;
    // The legs commanded while the samples in [from, to] can feel them, and where the first starts
    // (relative to the corner point, the end of legs[corner]).
    std::size_t lo = corner, hi = corner;
    while (lo > 0 && legs[lo - 1].finish() >= from) --lo;
    while (hi + 1 < legs.size() && legs[hi + 1].start() <= to) ++hi;
    AxisVector first = AxisVector::Zero();
    for (std::size_t k = lo; k <= corner; ++k) first -= legs[k].delta;
    double worst = 0.0;
    for (double k = std::ceil(from / period); k * period <= to; ++k) {
        const AxisVector p = relative_position(legs, corner, k * period);
        double nearest = HUGE_VAL;
        AxisVector a = first;
        for (std::size_t m = lo; m <= hi; ++m) {
            const AxisVector b = a + legs[m].delta;
            nearest = std::min(nearest, chord_distance(p - a, p - b));
            a = b;
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}

}  // namespace firtp
