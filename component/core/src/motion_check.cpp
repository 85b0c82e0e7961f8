#include <firtp/motion_check.hpp>

#include <firtp/junction.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace firtp {

namespace {

// A plan designed to reach a limit reaches it within rounding: 1.4e-9 above it was seen (random
// machine 41, program 404), refused with 1e-9; 1.4e-8 where a step's jerk stage is a thousandth
// of its box (machine 61, program 1689), refused with 1e-8. The samples are held to 1e-6.
constexpr double slack = 1.0 + 1e-7;
// A second stage this much shorter than the first moves nothing (a junction step of almost no
// speed change has a box of ~1e-17 s): checked as one stage, whose jump is then exact.
constexpr double negligible_stage = 1e-9;
// Knots this close are one: the steps that meet at a junction start on sums that round differently.
constexpr double same_knot = 1e-12;

// A knot of the sum: a time at which one step's edge (LimitSweep::Edge) changes the jerk (two-stage
// kernels), the acceleration (one-stage) or the velocity (sharp steps) by its jump, or by -jump.
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

// The knots of one step: its jumps go to edges[e]; the knots after `from` and up to `to` are
// appended at knots[n...] (returns the new n); those before it are summed into the state at `from`
// (v, a, j). Both from the same knot times, so a knot that rounds onto `from` is counted exactly
// once. Only the first `axes` entries of the vectors are computed.
// (Axes > 0: that many axes, known to the compiler; 0: `axes` of them.)
// A step is open from its first knot to its last; `settled` sums the steps closed before `from`,
// `open` counts those open at it.
template <int Axes>
std::size_t add_knots(LimitSweep::Edge& edge, std::uint32_t e, std::vector<Knot>& knots, std::size_t n, const AxisVector& step,
                      double start, const Kernel& k, double from, double to, int runtime_axes, AxisVector& v, AxisVector& a,
                      AxisVector& j, AxisVector& settled, int& open) {
    const int axes = Axes > 0 ? Axes : runtime_axes;
    double ta = 0.0, tb = 0.0;
    stages(k, ta, tb);
    const bool one_stage = tb <= negligible_stage * ta;  // (a stage of 1e-17 s: jerks of 1e21 to cancel)
    const double divisor = ta <= 0.0 ? 0.0 : one_stage ? ta : ta * tb;
    edge.order = ta <= 0.0 ? 1 : one_stage ? 2 : 3;
    for (int i = 0; i < axes; ++i) edge.jump[i] = divisor != 0.0 ? step[i] / divisor : step[i], edge.step[i] = step[i];
    const AxisVector& jump = edge.jump;
    const double close = ta <= 0.0 ? start : one_stage ? start + ta : start + ta + tb;  // its last knot
    // At `from` the state holds every knot before it and those at it but the kernel's start (the
    // response is 0 there, its right-hand derivatives are not).
    auto listed = [&](double t) { return t > from || (t == from && t == start); };
    if (!listed(close)) {
        for (int i = 0; i < axes; ++i) settled[i] += step[i];
    } else if (!listed(start)) {
        ++open;
    }
    auto add = [&](double t, bool flip, std::uint32_t ends = 0) {
        if (listed(t)) {
            if (t <= to && n < knots.size()) knots[n++] = {t, e, (flip ? Knot::flip : 0u) | ends};
            return;
        }
        const double dt = from - t;
        if (edge.order == 3) {
            const double half = 0.5 * dt * dt;
            for (int i = 0; i < axes; ++i) {
                const double value = flip ? -jump[i] : jump[i];
                j[i] += value, a[i] += value * dt, v[i] += value * half;
            }
        } else if (edge.order == 2) {
            for (int i = 0; i < axes; ++i) {
                const double value = flip ? -jump[i] : jump[i];
                a[i] += value, v[i] += value * dt;
            }
        } else {
            for (int i = 0; i < axes; ++i) v[i] += jump[i];
        }
    };
    if (ta <= 0.0) {
        add(start, false, Knot::first | Knot::last);
    } else if (one_stage) {
        add(start, false, Knot::first);
        add(close, true, Knot::last);
    } else {
        add(start, false, Knot::first);
        add(start + tb, true);
        add(start + ta, true);
        add(close, false, Knot::last);
    }
    return n;
}

template <int Axes>
struct Checker {
    int axes;
    // Per axis and derivative (velocity, acceleration, jerk): limit * slack, +inf where there is no
    // limit (0).
    double threshold[3][max_axes];
    LimitCheck result;

    explicit Checker(const MachineLimits& limits) : axes(Axes > 0 ? Axes : limits.axes) {
        for (int i = 0; i < axes; ++i) {
            const double l[3] = {limits.axis[i].max_velocity, limits.axis[i].max_acceleration, limits.axis[i].max_jerk};
            for (int d = 0; d < 3; ++d) threshold[d][i] = l[d] > 0.0 ? l[d] * slack : HUGE_VAL;
        }
    }
    void over(double value, double t, int axis, int derivative) {
        if (std::abs(value) > threshold[derivative - 1][axis] && result.ok) result = {false, t, axis, derivative, value};
    }
    void state(double t, const AxisVector& v, const AxisVector& a) {
        for (int i = 0; i < (Axes > 0 ? Axes : axes); ++i) {
            over(v[i], t, i, 1);
            over(a[i], t, i, 2);
        }
    }
};

}  // namespace

// An edge's slot is kept only when one of its knots is (at most one a knot), so the edges never
// run out before the knots do.
LimitSweep::LimitSweep(std::size_t max_legs) : edges_(max_legs * 8 + 1), knots_(max_legs * 8) {}

LimitCheck LimitSweep::check(std::span<const TimedLeg> legs, double from, double to, const MachineLimits& limits,
                             double period) {
    switch (limits.axes) {  // the common machines with their axes known to the compiler (unrolled)
    case 3: return sweep<3>(legs, from, to, limits, period);
    case 2: return sweep<2>(legs, from, to, limits, period);
    case 4: return sweep<4>(legs, from, to, limits, period);
    default: return sweep<0>(legs, from, to, limits, period);
    }
}

template <int Axes>
LimitCheck LimitSweep::sweep(std::span<const TimedLeg> legs, double from, double to, const MachineLimits& limits, double period) {
    std::vector<Knot>& knots = knots_;
    const int axes = Axes > 0 ? Axes : limits.axes;  // the only entries computed and checked
    std::size_t n = 0;
    AxisVector v = AxisVector::Zero(), a = AxisVector::Zero(), j = AxisVector::Zero();
    std::uint32_t e = 0;
    // Where no step is open the sums are exact: the velocity is that of the steps closed, the
    // acceleration and jerk 0. The running sums are put back there, or their rounding grows with
    // the time swept (3.5e-7 of a velocity limit 18 s on: a refusal no corner could mend, retried
    // until the corners crawled; RateChange.AnOverrideAndBackDoesNotLeaveTheToolCrawling).
    AxisVector settled = AxisVector::Zero();
    int open = 0;
    auto settle = [&] {
        for (int i = 0; i < axes; ++i) v[i] = settled[i], a[i] = 0.0, j[i] = 0.0;
    };
    auto emit = [&](const AxisVector& step, double start, const Kernel& k) {
        const std::size_t before = n;
        n = add_knots<Axes>(edges_[e], e, knots, n, step, start, k, from, to, axes, v, a, j, settled, open);
        if (n > before) ++e;
    };
    // A leg's falling edge waits for the next leg: where that one rises on the same step (the
    // same kernel at the same time, to same_knot: a junction), the two edges are one, of up' - up.
    // Apart, a step of 3e-15 s between two legs of 72 mm/s jumped by +-2e16 mm/s^2, and the sum's
    // rounding (4 mm/s^2) refused a plan at its limit (random machines seed 7, program 486).
    AxisVector fall;
    const TimedLeg* falling = nullptr;
    for (const TimedLeg& leg : legs) {
        if (!(leg.tv > 0.0) || leg.finish() < from) {  // no motion, or both steps done (it adds nothing)
            if (falling != nullptr) emit(fall, falling->rise + falling->fall, falling->falling), falling = nullptr;
            continue;
        }
        AxisVector up;
        for (int i = 0; i < axes; ++i) up[i] = leg.delta[i] / leg.tv;
        if (falling != nullptr && falling->falling.a == leg.rising.a && falling->falling.b == leg.rising.b &&
            falling->falling.chain == leg.rising.chain && std::abs(falling->rise + falling->fall - leg.rise) <= same_knot) {
            for (int i = 0; i < axes; ++i) fall[i] += up[i];
            emit(fall, leg.rise, leg.rising);
        } else {
            if (falling != nullptr) emit(fall, falling->rise + falling->fall, falling->falling);
            emit(up, leg.rise, leg.rising);
        }
        for (int i = 0; i < axes; ++i) fall[i] = -up[i];
        falling = &leg;
    }
    if (falling != nullptr) emit(fall, falling->rise + falling->fall, falling->falling);
    // The same comparisons of t as sorting the knots with their jumps would make: the same order,
    // ties included.
    std::sort(knots.begin(), knots.begin() + static_cast<std::ptrdiff_t>(n), [](const Knot& x, const Knot& y) { return x.t < y.t; });
    if (open == 0) settle();
    Checker<Axes> c(limits);
    c.state(from, v, a);
    double t = from;
    for (std::size_t k = 0; k <= n; ++k) {
        const double next = k < n ? knots[k].t : to;
        const double dt = next - t;
        if (dt > 0.0) {
            // Knots that coincide are computed from sums that round differently: an interval of a
            // nanosecond between them has no jerk that moves anything.
            const bool real = dt > 1e-9;
            for (int i = 0; i < axes; ++i) {
                if (real) c.over(j[i], t, i, 3);
                // A velocity extremum inside the interval, where the acceleration crosses zero
                // (-a / j > 0: a and j of opposite signs).
                if ((j[i] > 0.0 && a[i] < 0.0) || (j[i] < 0.0 && a[i] > 0.0)) {
                    const double tz = -a[i] / j[i];
                    if (tz > 0.0 && tz < dt) c.over(v[i] + a[i] * tz + 0.5 * j[i] * tz * tz, t + tz, i, 1);
                }
            }
            const double half = 0.5 * dt * dt;
            for (int i = 0; i < axes; ++i) {
                v[i] += a[i] * dt + j[i] * half;
                a[i] += j[i] * dt;
            }
            t = next;
            c.state(t, v, a);
        }
        if (k == n) break;
        // Every knot at this time at once: the jumps of two legs meeting at a junction cancel.
        AxisVector jump = AxisVector::Zero();
        bool jumps = false, moved = false;
        for (; k < n && knots[k].t <= t + same_knot; ++k) {
            const Edge& edge = edges_[knots[k].edge];
            const std::uint32_t flags = knots[k].flags;
            const bool flip = (flags & Knot::flip) != 0;
            AxisVector& target = edge.order == 3 ? j : edge.order == 2 ? a : v;
            for (int i = 0; i < axes; ++i) {
                const double value = flip ? -edge.jump[i] : edge.jump[i];
                target[i] += value;
                if (edge.order == 2) jump[i] += value;
            }
            if (flags & Knot::first) ++open;
            if (flags & Knot::last) {
                --open;
                for (int i = 0; i < axes; ++i) settled[i] += edge.step[i];
            }
            jumps = jumps || edge.order == 2;
            moved = moved || edge.order != 3;  // a jump in jerk leaves v and a as they were checked
        }
        --k;
        if (open == 0) settle(), moved = true;
        if (jumps)
            for (int i = 0; i < axes; ++i)  // a jump in acceleration, as the samples' differences see it
                if (jump[i] != 0.0) c.over(jump[i] / period, t, i, 3);
        if (moved) c.state(t, v, a);
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

// The kernel's step response at x is exactly 0, with its derivatives (Kernel::step).
bool not_begun(const Kernel& k, double x) { return k.chain == nullptr && k.a > 0.0 && x <= kernel_detail::started_after; }

// sum_legs' sum over the legs [lo, hi) that may move at t, into s; Axes > 0: a fixed count (= axes),
// summed in locals (the same additions in the same order).
template <bool Derivatives, int Axes>
void add_moving(std::span<const TimedLeg> legs, std::size_t corner, double t, std::size_t lo, std::size_t hi, int axes,
                AxisState& s) {
    const int n = Axes > 0 ? Axes : axes;
    double p_sum[max_axes], v_sum[max_axes], a_sum[max_axes], j_sum[max_axes];
    for (int i = 0; i < n; ++i) {
        p_sum[i] = s.position[i];
        if constexpr (Derivatives) v_sum[i] = s.velocity[i], a_sum[i] = s.acceleration[i], j_sum[i] = s.jerk[i];
    }
    for (std::size_t k = lo; k < hi; ++k) {
        const TimedLeg& leg = legs[k];
        if (!(leg.tv > 0.0)) continue;
        // A leg after the corner that has not begun adds exactly 0 (at most a zero's sign, which
        // no distance sees).
        if (k > corner && not_begun(leg.rising, t - leg.rise) && not_begun(leg.falling, t - leg.rise - leg.fall)) continue;
        const double sign = k <= corner ? 1.0 : 0.0;
        if constexpr (Derivatives) {
            const StepSample up = leg.rising.step(t - leg.rise);
            const StepSample down = leg.falling.step(t - leg.rise - leg.fall);
            const double p = (up.position - down.position) / leg.tv - sign;
            const double v = (up.velocity - down.velocity) / leg.tv;
            const double a = (up.acceleration - down.acceleration) / leg.tv;
            const double j = (up.jerk - down.jerk) / leg.tv;
            for (int i = 0; i < n; ++i) {
                const double d = leg.delta[i];
                p_sum[i] += d * p;
                v_sum[i] += d * v;
                a_sum[i] += d * a;
                j_sum[i] += d * j;
            }
        } else {
            const double p = (leg.rising.step_position(t - leg.rise) - leg.falling.step_position(t - leg.rise - leg.fall)) / leg.tv - sign;
            for (int i = 0; i < n; ++i) p_sum[i] += leg.delta[i] * p;
        }
    }
    for (int i = 0; i < n; ++i) {
        s.position[i] = p_sum[i];
        if constexpr (Derivatives) s.velocity[i] = v_sum[i], s.acceleration[i] = a_sum[i], s.jerk[i] = j_sum[i];
    }
}

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
    // The other axes' sums stay 0. Three axes (the common machine) with a loop the compiler unrolls.
    if (legs.front().axes == 3) add_moving<Derivatives, 3>(legs, corner, t, lo, hi, 3, s);
    else add_moving<Derivatives, 0>(legs, corner, t, lo, hi, legs.front().axes, s);
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

Approach closest_approach(std::span<const TimedLeg> legs, std::size_t corner, double guess, double period, int phases,
                          const ApproachBounds& bounds, const AxisVector& offset) {
    Approach best{HUGE_VAL, guess, HUGE_VAL, HUGE_VAL, guess};
    // Positions from the corner point, `offset` past the end of legs[corner].
    auto relative_position = [&](std::span<const TimedLeg> l, std::size_t c, double t) -> AxisVector {
        return firtp::relative_position(l, c, t) - offset;
    };
    auto relative_state = [&](std::span<const TimedLeg> l, std::size_t c, double t) {
        AxisState s = firtp::relative_state(l, c, t);
        s.position -= offset;
        return s;
    };
    const double sag = period * period / 8.0 * bounds.acceleration;
    // Any point of the path is at least as far from the corner as the closest: where the guess
    // itself is close enough, so is the approach.
    if (bounds.enough > 0.0) {
        const double d = relative_position(legs, corner, guess).norm();
        if (d + sag <= bounds.enough) {
            best.smooth = d;
            best.sampled = best.distance = d + sag;
            best.latest = guess + period;
            return best;
        }
    }
    double t = guess, acceleration = HUGE_VAL;  // |a| at the best point
    for (int i = 0; i < approach_steps; ++i) {
        best.latest = std::max(best.latest, t);
        const AxisState s = relative_state(legs, corner, t);
        const double d = s.position.norm();
        if (d < best.smooth) best.smooth = d, best.time = t, acceleration = s.acceleration.norm();
        // Newton on (x - P) . v = 0, the derivative of |x - P|^2 / 2.
        const double f = s.position.dot(s.velocity);
        const double df = s.velocity.squaredNorm() + s.position.dot(s.acceleration);
        if (!(df > 0.0)) break;
        const double step = std::clamp(-f / df, -approach_step_periods * period, approach_step_periods * period);
        // Within 1 ns of the minimum: the distance here exceeds it by about (v 1 ns)^2 / 2d.
        if (std::abs(step) < 1e-9) break;
        t += step;
    }
    if (best.smooth > bounds.too_far) {
        best.sampled = best.distance = best.smooth;
        return best;
    }
    // The drives go straight from sample to sample (t = (k + phase) period): the chords around
    // the approach, for each phase the worst. The chord across the approach's time is within the
    // sag of the path there, whatever the phase (|a| over its period from the one at the approach).
    const double near = std::min(sag, period * period / 8.0 * (acceleration + bounds.jerk * period));
    if (best.smooth + near <= bounds.enough) {
        best.sampled = best.smooth + near;
        best.distance = best.sampled;
        best.latest = std::max(best.latest, best.time + period);
        return best;
    }
    // Per phase the nearest chord, and the worst phase's. A phase whose chords cannot come
    // farther than the worst found so far is left out, and so is the rest of a phase's chords
    // once one is no farther: the same answer from fewer positions. The chord across the approach
    // time t* from t1 to t2 passes within |p(t*)| + (t* - t1)(t2 - t*) / 2 max |a| of the corner
    // (linear interpolation's error), |a| within J T of the approach's. Phases go from the most
    // centred on t* (the farthest chord, where the path bends) outwards.
    struct Phase {
        double phase, k0, spread;  // spread: (t* - t1)(t2 - t*) / 2
    };
    std::array<Phase, max_phases> order;
    const int n = std::clamp(phases, 1, max_phases);
    for (int f = 0; f < n; ++f) {
        Phase& x = order[f];
        x.phase = static_cast<double>(f) / n;
        x.k0 = std::floor(best.time / period - x.phase);
        const double t1 = (x.k0 + x.phase) * period, t2 = (x.k0 + 1 + x.phase) * period;
        x.spread = 0.5 * std::max(best.time - t1, 0.0) * std::max(t2 - best.time, 0.0);
        best.latest = std::max(best.latest, (x.k0 + sampled_chords + 1 + x.phase) * period);
        for (int g = f; g > 0 && order[g - 1].spread < order[g].spread; --g) std::swap(order[g - 1], order[g]);
    }
    const double bend = std::min(bounds.acceleration, acceleration + bounds.jerk * period);
    best.sampled = 0.0;
    for (int f = 0; f < n; ++f) {
        const Phase& x = order[f];
        // 1e-9: what rounding in the positions could add to a chord's distance, and more.
        if (f > 0 && best.smooth + x.spread * bend <= best.sampled * (1.0 - 1e-9)) break;
        const AxisVector p = relative_position(legs, corner, (x.k0 + x.phase) * period);
        const AxisVector q = relative_position(legs, corner, (x.k0 + 1 + x.phase) * period);
        double nearest = chord_distance(p, q);
        AxisVector later = p;  // the chords before the approach, back from it
        for (int k = 1; k <= sampled_chords && nearest > best.sampled; ++k) {
            const AxisVector earlier = relative_position(legs, corner, (x.k0 - k + x.phase) * period);
            nearest = std::min(nearest, chord_distance(earlier, later));
            later = earlier;
        }
        AxisVector earlier = q;  // ... and after it
        for (int k = 2; k <= sampled_chords + 1 && nearest > best.sampled; ++k) {
            const AxisVector next = relative_position(legs, corner, (x.k0 + k + x.phase) * period);
            nearest = std::min(nearest, chord_distance(earlier, next));
            earlier = next;
        }
        best.sampled = std::max(best.sampled, nearest);
    }
    best.distance = std::max(best.smooth, best.sampled);
    return best;
}

ApproachBounds chain_bounds(std::span<const TimedLeg> legs, const FirChain& chain, double from, double to) {
    const FilterTimes& f = chain.filters();  // T1 >= T2 >= ... (FirChain checks)
    const double earliest = from - chain.delay();
    double speeds = 0.0;
    for (const TimedLeg& l : legs) {
        if (!(l.tv > 0.0)) continue;
        const double v = l.delta.norm() / l.tv;
        if (l.rise >= earliest && l.rise <= to) speeds += v;
        if (l.rise + l.fall >= earliest && l.rise + l.fall <= to) speeds += v;
    }
    ApproachBounds b;
    b.acceleration = speeds / f.T[0];
    b.jerk = f.stages > 1 ? speeds / (f.T[0] * f.T[1]) : HUGE_VAL;
    return b;
}

double contour_error(std::span<const TimedLeg> legs, std::size_t corner, double at, double width, double period,
                     double* latest) {
    const double from = at - contour_reach(width, period), to = at + contour_reach(width, period);
    if (latest != nullptr) *latest = to;
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
