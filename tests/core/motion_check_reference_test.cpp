// The closed-form checks give, bit for bit, what their first, plainer forms gave (main at e606b27,
// with 5c02b7e's knots taken together at one time, a negligible second stage as one stage, and
// since 2026-12-02 a junction's two edges as one): the
// limit sweep sorted whole knots over all nine axes, and the sums visited every leg within reach. Their faster forms (docs/BENCHMARKS.md, "Planning cost") must not change a single plan,
// so each is held here to that reference on random legs made to hit the awkward cases: knots at
// the same time (a leg's fall is the next one's rise), one-stage and sharp kernels, motion at and
// just past the limits, legs that have not begun.
#include <firtp/motion_check.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

using namespace firtp;

namespace {

// ---- Reference: the sweep as it was ------------------------------------------------------------

struct RefKnot {
    double t;
    AxisVector value;
    int order;
    int ends = 0;  // 1: the step's first knot, 2: its last (since 2026-12-06)
    AxisVector step = AxisVector::Zero();
};

void ref_stages(const Kernel& k, double& a, double& b) {
    a = k.a;
    b = k.b;
}

// Since 2026-12-06 the steps closed before `from` are summed in `settled` and those open at it
// counted in `open`.
std::size_t ref_add_knots(std::vector<RefKnot>& knots, std::size_t n, const AxisVector& dv, double start, const Kernel& k,
                          double from, double to, AxisVector& v, AxisVector& a, AxisVector& j, AxisVector& settled, int& open) {
    double ta = 0.0, tb = 0.0;
    ref_stages(k, ta, tb);
    const bool one = tb <= 1e-9 * ta;
    const double close = ta <= 0.0 ? start : one ? start + ta : start + ta + tb;
    auto listed = [&](double t) { return t > from || (t == from && t == start); };
    if (!listed(close)) settled += dv;
    else if (!listed(start)) ++open;
    auto add = [&](double t, const AxisVector& value, int order, int ends = 0) {
        if (listed(t)) {
            if (t <= to && n < knots.size()) knots[n++] = {t, value, order, ends, dv};
            return;
        }
        const double dt = from - t;
        if (order == 3) j += value, a += value * dt, v += value * (0.5 * dt * dt);
        else if (order == 2) a += value, v += value * dt;
        else v += value;
    };
    if (ta <= 0.0) {
        add(start, dv, 1, 3);
    } else if (one) {  // a negligible second stage: one stage (5c02b7e)
        add(start, dv / ta, 2, 1);
        add(start + ta, -dv / ta, 2, 2);
    } else {
        const AxisVector jk = dv / (ta * tb);
        add(start, jk, 3, 1);
        add(start + tb, -jk, 3);
        add(start + ta, -jk, 3);
        add(start + ta + tb, jk, 3, 2);
    }
    return n;
}

LimitCheck ref_check(std::span<const TimedLeg> legs, double from, double to, const MachineLimits& limits, double period,
                     bool leave_out_finished = true) {
    constexpr double slack = 1.0 + 1e-9;
    std::vector<RefKnot> knots(legs.size() * 8);
    std::size_t n = 0;
    AxisVector v = AxisVector::Zero(), a = AxisVector::Zero(), j = AxisVector::Zero();
    AxisVector settled = AxisVector::Zero();
    int open = 0;
    // Since 2026-12-02 a leg's falling edge and the next leg's rising edge on the same kernel at
    // the same time to 1e-12 s (a junction's step) are one edge at the rise, of the two
    // velocities' difference.
    const TimedLeg* previous = nullptr;  // the leg whose falling edge is not added yet
    auto add_fall = [&](const TimedLeg& leg) {
        n = ref_add_knots(knots, n, AxisVector(-(leg.delta / leg.tv)), leg.rise + leg.fall, leg.falling, from, to, v, a, j, settled, open);
    };
    for (const TimedLeg& leg : legs) {
        // A leg both of whose steps are done before `from` adds 0 to the state there: since
        // 2026-11-28 it is left out (it added only its sums' rounding).
        if (!(leg.tv > 0.0) || (leave_out_finished && leg.finish() < from)) {
            if (previous != nullptr) add_fall(*previous);
            previous = nullptr;
            continue;
        }
        const AxisVector dv = leg.delta / leg.tv;
        const bool junction = previous != nullptr && previous->falling.a == leg.rising.a && previous->falling.b == leg.rising.b &&
                              std::abs(previous->rise + previous->fall - leg.rise) <= 1e-12;
        if (junction) {
            n = ref_add_knots(knots, n, AxisVector(dv - previous->delta / previous->tv), leg.rise, leg.rising, from, to, v, a, j, settled, open);
        } else {
            if (previous != nullptr) add_fall(*previous);
            n = ref_add_knots(knots, n, dv, leg.rise, leg.rising, from, to, v, a, j, settled, open);
        }
        previous = &leg;
    }
    if (previous != nullptr) add_fall(*previous);
    std::sort(knots.begin(), knots.begin() + static_cast<std::ptrdiff_t>(n),
              [](const RefKnot& x, const RefKnot& y) { return x.t < y.t; });
    // Since 2026-12-06, where no step is open the sums are put back on their exact values.
    auto settle = [&] {
        if (open == 0) v = settled, a.setZero(), j.setZero();
    };
    settle();
    LimitCheck result;
    auto over = [&](double value, double limit, double t, int axis, int derivative) {
        if (limit > 0.0 && std::abs(value) > limit * slack && result.ok) result = {false, t, axis, derivative, value};
    };
    auto state = [&](double t) {
        for (int i = 0; i < limits.axes; ++i) {
            over(v[i], limits.axis[i].max_velocity, t, i, 1);
            over(a[i], limits.axis[i].max_acceleration, t, i, 2);
        }
    };
    state(from);
    double t = from;
    for (std::size_t k = 0; k <= n; ++k) {
        const double next = k < n ? knots[k].t : to;
        const double dt = next - t;
        if (dt > 0.0) {
            const bool real = dt > 1e-9;
            for (int i = 0; i < limits.axes; ++i) {
                if (real) over(j[i], limits.axis[i].max_jerk, t, i, 3);
                if (j[i] != 0.0) {
                    const double tz = -a[i] / j[i];
                    if (tz > 0.0 && tz < dt) over(v[i] + a[i] * tz + 0.5 * j[i] * tz * tz, limits.axis[i].max_velocity, t + tz, i, 1);
                }
            }
            v += a * dt + j * (0.5 * dt * dt);
            a += j * dt;
            t = next;
            state(t);
        }
        if (k == n) break;
        // The knots within 1e-12 s of each other at once (5c02b7e).
        AxisVector jump = AxisVector::Zero();
        bool jumps = false;
        for (; k < n && knots[k].t <= t + 1e-12; ++k) {
            const RefKnot& knot = knots[k];
            if (knot.order == 2) jump += knot.value, jumps = true;
            (knot.order == 3 ? j : knot.order == 2 ? a : v) += knot.value;
            if (knot.ends & 1) ++open;
            if (knot.ends & 2) --open, settled += knot.step;
        }
        --k;
        settle();
        if (jumps)
            for (int i = 0; i < limits.axes; ++i)
                if (jump[i] != 0.0) over(jump[i] / period, limits.axis[i].max_jerk, t, i, 3);
        state(t);
        if (!result.ok) break;
    }
    return result;
}

// ---- Reference: the sums as they were ----------------------------------------------------------

AxisState ref_relative_state(std::span<const TimedLeg> legs, std::size_t corner, double t) {
    AxisState s;
    s.time = t;
    std::size_t lo = 0, hi = legs.size();
    const double reach = legs.front().reach;
    if (reach > 0.0) {
        const double margin = 1e-9 + 1e-12 * std::abs(t);
        lo = static_cast<std::size_t>(std::partition_point(legs.begin(), legs.end(), [&](const TimedLeg& l) {
                                          return l.fall_centre + reach < t - margin;
                                      }) - legs.begin());
        hi = static_cast<std::size_t>(std::partition_point(legs.begin() + static_cast<std::ptrdiff_t>(lo), legs.end(),
                                                           [&](const TimedLeg& l) { return l.rise_centre - reach <= t + margin; }) -
                                      legs.begin());
        const AxisVector& corner_end = corner + 1 < legs.size() ? legs[corner + 1].before : AxisVector(legs[corner].before + legs[corner].delta);
        const AxisVector done = lo < legs.size() ? legs[lo].before : AxisVector(legs.back().before + legs.back().delta);
        const AxisVector waiting = hi < legs.size() ? legs[hi].before : AxisVector(legs.back().before + legs.back().delta);
        if (lo > corner + 1) s.position += done - corner_end;
        if (hi <= corner) s.position -= corner_end - waiting;
    }
    const int axes = legs.front().axes;
    for (std::size_t k = lo; k < hi; ++k) {
        const TimedLeg& leg = legs[k];
        if (!(leg.tv > 0.0)) continue;
        const double sign = k <= corner ? 1.0 : 0.0;
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
    }
    return s;
}

// ---- Random legs -------------------------------------------------------------------------------

// A chain of legs as the look-ahead builds them: each leg's falling step is the next one's rising
// step (often at exactly the same time: ties), kernels of two stages, now and then one stage or a
// sharp step; speeds near what `limits` allow, so that some sets pass and some do not.
std::vector<TimedLeg> random_legs(std::mt19937_64& rng, int axes, int count) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), speed(20.0, 320.0), duration(0.0005, 0.04), t1(0.0, 0.06);
    std::uniform_int_distribution<int> kind(0, 9);
    std::vector<TimedLeg> legs;
    double centre = 0.0;
    Kernel step = two_stage(0.03, 0.02);
    for (int k = 0; k < count; ++k) {
        AxisVector u = AxisVector::Zero();
        for (int i = 0; i < axes; ++i) u[i] = unit(rng);
        u.normalize();
        const double tv = duration(rng);
        Kernel next;
        const int which = kind(rng);
        if (which == 0) next = Kernel{};                          // sharp
        else if (which == 1) next = two_stage(t1(rng), 0.0);      // one stage
        else if (which == 2) next = step;                         // the same kernel again: ties
        else next = two_stage(t1(rng), 0.02);
        TimedLeg leg;
        leg.tv = tv;
        leg.delta = u * (speed(rng) * tv);
        leg.rise = centre - 0.5 * step.width();
        leg.fall = (centre + tv - 0.5 * next.width()) - leg.rise;
        leg.rising = step;
        leg.falling = next;
        legs.push_back(leg);
        centre += tv;
        step = next;
    }
    return legs;
}

// A machine `scale` times stronger than 300 mm/s, 5000 mm/s^2, 1e5 mm/s^3 (the axes a little apart).
MachineLimits limits_of(int axes, double scale) {
    MachineLimits m;
    m.axes = axes;
    for (int i = 0; i < axes; ++i) m.axis[i] = {300.0 * scale, (5000.0 + 1000.0 * i) * scale, 1e5 * (1.0 + 0.5 * i) * scale};
    return m;
}

bool same(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

}  // namespace

TEST(MotionCheckReference, LimitSweepGivesTheSameResultBitForBit) {
    std::mt19937_64 rng(13);
    int failed = 0, passed = 0, left_out = 0;
    std::uniform_real_distribution<double> strength(0.0, std::log(400.0));
    for (int axes : {1, 2, 3, 5, 9}) {
        LimitSweep sweep(256);
        for (int run = 0; run < 300; ++run) {
            const MachineLimits limits = limits_of(axes, std::exp(strength(rng)));
            const std::vector<TimedLeg> legs = random_legs(rng, axes, 2 + static_cast<int>(rng() % 40));
            const double end = legs.back().finish();
            std::uniform_real_distribution<double> cut(-0.05, 0.5 * end);
            const double from = std::max(0.0, cut(rng));
            const LimitCheck got = sweep.check(legs, from, end, limits, 0.001);
            const LimitCheck want = ref_check(legs, from, end, limits, 0.001);
            ASSERT_EQ(got.ok, want.ok) << "axes " << axes << " run " << run;
            ASSERT_TRUE(same(got.time, want.time) && got.axis == want.axis && got.derivative == want.derivative &&
                        same(got.value, want.value))
                << "axes " << axes << " run " << run << ": " << got.time << " " << got.value << " against " << want.time
                << " " << want.value;
            (got.ok ? passed : failed) += 1;
            // With the finished legs summed in, as before 2026-11-28: the same outcome, to rounding.
            const LimitCheck summed = ref_check(legs, from, end, limits, 0.001, false);
            ASSERT_EQ(summed.ok, want.ok) << "axes " << axes << " run " << run;
            if (!want.ok) {
                EXPECT_EQ(summed.axis, want.axis);
                EXPECT_EQ(summed.derivative, want.derivative);
                EXPECT_NEAR(summed.time, want.time, 1e-12);
                EXPECT_NEAR(summed.value, want.value, 1e-9 * std::abs(want.value));
            }
            left_out += std::count_if(legs.begin(), legs.end(), [&](const TimedLeg& l) { return l.tv > 0.0 && l.finish() < from; }) > 0;
        }
    }
    // Both outcomes were tried (else the comparison proves little), and legs done before `from`.
    EXPECT_GT(passed, 100);
    EXPECT_GT(failed, 100);
    EXPECT_GT(left_out, 100);
}

TEST(MotionCheckReference, SumsOverTheLegsGiveTheSameStateBitForBit) {
    std::mt19937_64 rng(17);
    for (int axes : {1, 3, 4, 9}) {
        for (int run = 0; run < 200; ++run) {
            std::vector<TimedLeg> legs = random_legs(rng, axes, 3 + static_cast<int>(rng() % 30));
            index_legs(legs);
            const std::size_t corner = rng() % (legs.size() - 1);
            const double end = legs.back().finish();
            for (int k = 0; k < 40; ++k) {
                const double t = end * (static_cast<double>(k) / 39.0) - 0.01;
                const AxisState got = relative_state(legs, corner, t);
                const AxisVector position = relative_position(legs, corner, t);
                const AxisState want = ref_relative_state(legs, corner, t);
                for (int i = 0; i < max_axes; ++i) {
                    // == rather than the bits: a leg that has not begun may leave a zero's sign.
                    ASSERT_EQ(got.position[i], want.position[i]) << "axes " << axes << " run " << run << " t " << t;
                    ASSERT_EQ(position[i], want.position[i]);
                    ASSERT_EQ(got.velocity[i], want.velocity[i]);
                    ASSERT_EQ(got.acceleration[i], want.acceleration[i]);
                    ASSERT_EQ(got.jerk[i], want.jerk[i]);
                }
            }
        }
    }
}

// Where the sweep holds the legs within the limits, a chord of the samples strays at most
// sag = period^2 / 8 |a|max from the path: the smooth approach plus sag bounds what the chords
// give, on every sample grid, so closest_approach may answer it without sampling them.
TEST(MotionCheckReference, ChordSagBoundsTheSampledApproach) {
    std::mt19937_64 rng(19);
    constexpr double period = 0.001;
    int within = 0, chords_worse = 0, by_jerks = 0;
    double closest = 0.0;  // the largest (sampled - smooth) / sag
    LimitSweep sweep(256);
    for (int axes : {1, 2, 3, 5}) {
        for (int run = 0; run < 1500; ++run) {
            std::vector<TimedLeg> legs = random_legs(rng, axes, 3 + static_cast<int>(rng() % 20));
            index_legs(legs);
            // A sharp step jumps in velocity: no acceleration bounds it (the sweep checks the jump's
            // velocity only), and the look-ahead does not use it for the bound either.
            const bool sharp = std::any_of(legs.begin(), legs.end(), [](const TimedLeg& l) {
                return l.rising.width() == 0.0 || l.falling.width() == 0.0;
            });
            // The weakest machine of limits_of's shape that these legs keep to: the bound as tight
            // as it gets on the most loaded axis.
            auto keeps = [&](double scale) { return sweep.check(legs, 0.0, legs.back().finish(), limits_of(axes, scale), period).ok; };
            if (sharp || !keeps(400.0)) continue;
            double lo = 0.01, hi = 400.0;
            for (int k = 0; k < 30; ++k) (keeps(std::sqrt(lo * hi)) ? hi : lo) = std::sqrt(lo * hi);
            const MachineLimits limits = limits_of(axes, hi);
            double acc2 = 0.0;
            for (int i = 0; i < axes; ++i) acc2 += std::pow(limits.axis[i].max_acceleration * (1.0 + 1e-6), 2);
            const double sag = period * period / 8.0 * std::sqrt(acc2);
            const std::size_t corner = rng() % (legs.size() - 1);
            const TimedLeg& c = legs[corner];
            const double guess = c.rise + c.fall + 0.5 * c.falling.width();
            const Approach sampled = closest_approach(legs, corner, guess, period, 8);
            // Enough at once: the guess's own distance plus sag.
            const double acc = std::sqrt(acc2);
            const Approach at_guess = closest_approach(legs, corner, guess, period, 8, {acc, HUGE_VAL, HUGE_VAL});
            ASSERT_EQ(at_guess.distance, relative_position(legs, corner, guess).norm() + sag);
            ASSERT_GE(at_guess.distance, sampled.distance) << "axes " << axes << " run " << run;
            // Enough only at the approach: Newton's, plus sag.
            const Approach at_approach = closest_approach(legs, corner, guess, period, 8, {acc, HUGE_VAL, sampled.smooth + sag});
            ASSERT_EQ(at_approach.distance, sampled.smooth + sag);
            ASSERT_GE(at_approach.distance, sampled.sampled) << "axes " << axes << " run " << run;
            // The sag from the acceleration at the approach and the jerk limit, where every kernel
            // has a jerk stage (one stage jumps in acceleration).
            const bool two_stages = std::all_of(legs.begin(), legs.end(), [](const TimedLeg& l) {
                return l.rising.b > 0.0 && l.falling.b > 0.0;
            });
            if (two_stages) {
                double jerk2 = 0.0;
                for (int i = 0; i < axes; ++i) jerk2 += std::pow(limits.axis[i].max_jerk * (1.0 + 1e-6), 2);
                const double jerk = std::sqrt(jerk2);
                const double near = period * period / 8.0 *
                                    (relative_state(legs, corner, sampled.time).acceleration.norm() + jerk * period);
                const Approach by_jerk = closest_approach(legs, corner, guess, period, 8, {HUGE_VAL, jerk, sampled.smooth + near});
                ASSERT_EQ(by_jerk.distance, sampled.smooth + near);
                ASSERT_GE(by_jerk.distance, sampled.sampled) << "axes " << axes << " run " << run;
                ++by_jerks;
            }
            ++within;
            chords_worse += sampled.sampled > sampled.smooth;
            closest = std::max(closest, (sampled.sampled - sampled.smooth) / sag);
        }
    }
    // Enough sets within the limits, and corners where the chords pass further out than the path
    // (where the bound is what holds the answer).
    std::printf("within the limits %d, chords further out than the path %d, by up to %.3f sag\n", within, chords_worse, closest);
    EXPECT_GT(within, 300);
    EXPECT_GT(chords_worse, 50);
    EXPECT_GT(by_jerks, 100);
}

// closest_approach's chords as they were sampled (main at 766bd6c): every chord within
// sampled_chords periods of the approach, on every phase.
double ref_sampled(std::span<const TimedLeg> legs, std::size_t corner, double time, double period, int phases, double* latest) {
    double sampled = 0.0;
    for (int f = 0; f < phases; ++f) {
        const double phase = static_cast<double>(f) / phases;
        const double k0 = std::floor(time / period - phase);
        double nearest = HUGE_VAL;
        AxisVector previous = relative_position(legs, corner, (k0 - sampled_chords + phase) * period);
        for (double k = k0 - sampled_chords + 1; k <= k0 + sampled_chords + 1; ++k) {
            *latest = std::max(*latest, (k + phase) * period);
            const AxisVector next = relative_position(legs, corner, (k + phase) * period);
            const AxisVector d = next - previous;
            const double dd = d.squaredNorm();
            const double u = dd > 0.0 ? std::clamp(-previous.dot(d) / dd, 0.0, 1.0) : 0.0;
            nearest = std::min(nearest, (previous + u * d).norm());
            previous = next;
        }
        sampled = std::max(sampled, nearest);
    }
    return sampled;
}

// The phases and chords closest_approach leaves out (their bound from the acceleration at the
// approach and the jerk) would not have changed its answer: the same as sampling every chord of
// every phase, bit for bit, on legs held to the limits the bounds come from.
TEST(MotionCheckReference, LeftOutPhasesDoNotChangeTheSampledApproach) {
    std::mt19937_64 rng(29);
    constexpr double period = 0.001;
    LimitSweep sweep(256);
    int compared = 0, bounded = 0;
    for (int axes : {1, 2, 3, 5}) {
        for (int run = 0; run < 1500; ++run) {
            std::vector<TimedLeg> legs = random_legs(rng, axes, 3 + static_cast<int>(rng() % 20));
            index_legs(legs);
            const bool two_stages = std::all_of(legs.begin(), legs.end(), [](const TimedLeg& l) {
                return l.rising.width() > 0.0 && l.falling.width() > 0.0 && l.rising.b > 0.0 && l.falling.b > 0.0;
            });
            auto keeps = [&](double scale) { return sweep.check(legs, 0.0, legs.back().finish(), limits_of(axes, scale), period).ok; };
            ApproachBounds bounds;  // none: every phase sampled (only the chords' early end applies)
            if (two_stages && keeps(400.0)) {
                double lo = 0.01, hi = 400.0;
                for (int k = 0; k < 30; ++k) (keeps(std::sqrt(lo * hi)) ? hi : lo) = std::sqrt(lo * hi);
                const MachineLimits limits = limits_of(axes, hi);
                double acc2 = 0.0, jerk2 = 0.0;
                for (int i = 0; i < axes; ++i) {
                    acc2 += std::pow(limits.axis[i].max_acceleration * (1.0 + 1e-6), 2);
                    jerk2 += std::pow(limits.axis[i].max_jerk * (1.0 + 1e-6), 2);
                }
                bounds = {std::sqrt(acc2), std::sqrt(jerk2), 0.0, HUGE_VAL};
                ++bounded;
            }
            const std::size_t corner = rng() % (legs.size() - 1);
            const TimedLeg& c = legs[corner];
            const double guess = c.rise + c.fall + 0.5 * c.falling.width();
            for (int phases : {1, 3, 8}) {
                const Approach got = closest_approach(legs, corner, guess, period, phases, bounds);
                double latest = got.time;
                const double want = ref_sampled(legs, corner, got.time, period, phases, &latest);
                ASSERT_EQ(got.sampled, want) << "axes " << axes << " run " << run << " phases " << phases;
                ASSERT_EQ(got.distance, std::max(got.smooth, want));
                ASSERT_GE(got.latest, latest);
                ++compared;
            }
        }
    }
    EXPECT_GT(bounded, 300);
    EXPECT_GT(compared, 10000);
}

// chain_bounds holds the acceleration and jerk of legs smoothed by the paper's chain, on random
// chains and legs, within the window it is asked about.
TEST(MotionCheckReference, ChainBoundsHold) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double tightest = 0.0, tightest_jerk = 0.0;  // the largest acceleration (jerk) found / the bound
    for (int run = 0; run < 300; ++run) {
        FilterTimes f;
        f.stages = 1 + static_cast<int>(rng() % 4);
        for (int i = 0; i < f.stages; ++i) f.T[i] = 0.002 + 0.15 * unit(rng);
        std::sort(f.T.begin(), f.T.begin() + f.stages, std::greater<>());
        const FirChain chain(f);
        const Kernel k{0.0, 0.0, &chain};
        std::vector<TimedLeg> legs;
        double start = 0.0;
        for (int n = 2 + static_cast<int>(rng() % 8); n > 0; --n) {
            TimedLeg l;
            l.tv = 0.001 + 0.2 * unit(rng);
            AxisVector u = AxisVector::Zero();
            for (int i = 0; i < 3; ++i) u[i] = unit(rng) - 0.5;
            l.delta = u.normalized() * (l.tv * (5.0 + 300.0 * unit(rng)));
            l.rise = start;
            l.fall = l.tv;
            l.rising = l.falling = k;
            legs.push_back(l);
            start += l.tv * unit(rng);  // overlaps of any length
        }
        index_legs(legs);
        const double end = legs.back().finish();
        const double from = end * unit(rng), to = from + 0.05 * unit(rng);
        const ApproachBounds bound = chain_bounds(legs, chain, from, to);
        for (int s = 0; s <= 200; ++s) {
            const double t = from + (to - from) * s / 200.0;
            const AxisState state = relative_state(legs, 0, t);
            ASSERT_LE(state.acceleration.norm(), bound.acceleration * (1.0 + 1e-9) + 1e-9) << "run " << run << " t " << t;
            if (bound.acceleration > 0.0) tightest = std::max(tightest, state.acceleration.norm() / bound.acceleration);
            if (f.stages > 1) {
                ASSERT_LE(state.jerk.norm(), bound.jerk * (1.0 + 1e-9) + 1e-9) << "run " << run << " t " << t;
                tightest_jerk = std::max(tightest_jerk, state.jerk.norm() / bound.jerk);
            } else {
                ASSERT_EQ(bound.jerk, HUGE_VAL);
            }
        }
    }
    EXPECT_GT(tightest, 0.5);  // not bounds so loose that they prove nothing
    EXPECT_GT(tightest_jerk, 0.5);
}
