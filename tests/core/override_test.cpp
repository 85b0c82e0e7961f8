// Feed override, hold, resume and abort at random moments, on machines with axis limits: the S-curve
// rate ramps fit in the reserve the planner leaves (rate_reserve), so velocity and acceleration
// hold at every sample, and velocity, acceleration and jerk in the finite differences (what a drive
// sees; between the planned instants the FIR output's jerk steps may add up for less than a period,
// which only shifted samples can show); the path, and so the tolerance, does
// not depend on the rate; holds stop within stop_time(); the end is exact. Seeded.
#include "support/limits.hpp"
#include "support/reference.hpp"
#include "support/separation.hpp"
#include "support/soak.hpp"

#include <firtp/measure.hpp>
#include <firtp/planner.hpp>
#include <firtp/time_scale.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>

using namespace firtp;
using firtp::test::xyz;

namespace {

struct Outcome {
    std::vector<AxisState> samples;
    std::vector<AxisVector> points{AxisVector::Zero()};
    double longest_stop = 0.0;  // s, from a hold or abort to rest
    bool aborted = false;
};

// Plans `blocks` and runs them, changing the rate at the given ticks.
Outcome run(const PlannerParameters& p, const std::vector<Block>& blocks, const std::vector<std::pair<int, double>>& events) {
    PlannerParameters q = p;
    q.queue_capacity = 64;
    Planner planner(q, AxisVector::Zero());
    Outcome r;
    std::size_t next = 0, event = 0;
    int hold_tick = -1;
    for (int k = 0; k < 2000000; ++k) {
        for (; next < blocks.size(); ++next) {
            const Result result = planner.add(blocks[next]);
            if (result == Result::queue_full) break;
            EXPECT_TRUE(result == Result::ok || result == Result::skipped) << static_cast<int>(result);
            r.points.push_back(blocks[next].target);
        }
        for (; event < events.size() && events[event].first == k; ++event) {
            if (events[event].second < 0.0) {  // abort: stop on the path, then drop the rest
                planner.abort();
                r.aborted = true;
                hold_tick = k;
                continue;
            }
            planner.set_rate(events[event].second);
            if (events[event].second == 0.0 && hold_tick < 0) hold_tick = k;
            if (events[event].second > 0.0) hold_tick = -1;
        }
        AxisState s;
        planner.tick(s);
        r.samples.push_back(s);
        if (hold_tick >= 0 && planner.time_scale().stopped()) {
            r.longest_stop = std::max(r.longest_stop, (k - hold_tick) * p.period);
            hold_tick = -1;
        }
        if (r.aborted && planner.take_flushed()) {
            break;
        }
        if (next == blocks.size() && planner.idle() && event == events.size()) break;
    }
    return r;
}

}  // namespace

TEST(RateLimits, FromTheAxisLimitsAndTheReserve) {
    PlannerParameters p;
    p.fixed_chain = true;  // the paper's clock; smoothing at the limits plans the override instead
    p.limits = test::uniform_limits(300, 5000, 1e5);
    const RateLimits r = rate_limits(p);
    // r' <= min(0.2 * 5000 / 300, 0.2 * 1e5 / (6 * 4000)); r'' = (0.2 * 1e5 - 3 r' 4000) / 300
    EXPECT_NEAR(r.max_slope, 0.2e5 / 24000, 1e-12);
    EXPECT_NEAR(r.max_curvature, (0.2e5 - 3 * r.max_slope * 4000) / 300, 1e-9);
    EXPECT_NEAR(stop_time(r, 1.0), 1 / r.max_slope + 2 * r.max_slope / r.max_curvature, 1e-12);
    std::printf("built-in machine: hold from 100 %% within %.3f s\n", stop_time(r, 1.0));
    p.max_rate = 1.5;  // planned for 150 %: v / 1.5, a 0.8 / 2.25, j 0.8 / 3.375
    const MachineLimits planned = planned_limits(p);
    EXPECT_NEAR(planned.axis[0].max_velocity, 200, 1e-12);
    EXPECT_NEAR(planned.axis[0].max_acceleration, 5000 * 0.8 / 2.25, 1e-9);
    EXPECT_NEAR(planned.axis[0].max_jerk, 1e5 * 0.8 / 3.375, 1e-6);
    p.rate_reserve = 0.0;
    EXPECT_STREQ(validate_rate(p), "the rate reserve must lie between 0 and 1 (a share of the acceleration and jerk limits)");
    p.rate_reserve = 0.2;
    p.fixed_chain = false;
    EXPECT_NEAR(planned_limits(p).axis[0].max_acceleration, 5000, 1e-12);  // all of it at 100 %
    p.max_rate = 0.5;
    EXPECT_STREQ(validate_rate(p), "the highest feed override must be at least 1 (100 %)");
}

TEST(RateLimits, OverrideHoldAndAbortAtRandomMomentsKeepLimitsToleranceAndEnd) {
    std::mt19937_64 rng(23 + test::random_seed_offset());  // soak runs: support/soak.hpp
    // Never fewer than 120: the counts of holds and aborts below are asserted.
    const int programs = std::max(120, test::random_scaled(120));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0, worst_stop_ratio = 0.0;
    int holds = 0, aborts = 0;
    for (int k = 0; k < programs; ++k) {
        PlannerParameters p;
        p.limits = test::uniform_limits(100 + 300 * unit(rng), 1000 + 9000 * unit(rng), 2e4 + 3e5 * unit(rng));
        p.fixed_chain = true;
        p.filters = test::chain_of({0.02 + 0.08 * unit(rng), 0.01 + 0.03 * unit(rng)});
        if (p.filters.T[1] > p.filters.T[0]) std::swap(p.filters.T[0], p.filters.T[1]);
        p.max_rate = k % 2 == 0 ? 1.0 : 1.0 + unit(rng);
        std::vector<Block> blocks;
        for (bool separated = false; !separated;) {  // paths that fold back onto themselves are drawn again
            blocks.clear();
            std::vector<AxisVector> points{AxisVector::Zero()};
            double widest = 0.0;
            const int n = 3 + static_cast<int>(rng() % 8);
            for (int i = 0; i < n; ++i) {
                const AxisVector d = xyz(unit(rng) - 0.5, unit(rng) - 0.5, 0.2 * (unit(rng) - 0.5)).normalized();
                Block b;
                b.target = points.back() + d * (1 + 30 * unit(rng));
                b.feed = 20 + 380 * unit(rng);
                b.tolerance = 0.01 + 0.5 * unit(rng);
                b.line = i + 1;
                blocks.push_back(b);
                points.push_back(b.target);
                widest = std::max(widest, b.tolerance);
            }
            separated = test::well_separated(points, 3 * widest + 400 * p.period * p.max_rate);
        }
        const Outcome reference = run(p, blocks, {});
        // Rate changes at random ticks while moving: overrides up to max_rate, holds, resumes.
        std::vector<std::pair<int, double>> events;
        int tick = 0;
        const int moving = static_cast<int>(reference.samples.size());
        for (int e = 0; e < 6; ++e) {
            tick += 1 + static_cast<int>(unit(rng) * moving / 4);
            const double u = unit(rng);
            events.emplace_back(tick, u < 0.3 ? 0.0 : u < 0.5 ? p.max_rate : p.max_rate * unit(rng));
        }
        // Finish at 100 %, or (one program in four) abort at a random moment instead.
        events.emplace_back(tick + 1 + static_cast<int>(unit(rng) * 500), k % 4 == 3 ? -1.0 : 1.0);
        const Outcome r = run(p, blocks, events);
        SCOPED_TRACE("program " + std::to_string(k));
        const double ratio = test::worst_ratio(r.samples, p.limits, false);
        worst = std::max(worst, ratio);
        ASSERT_LE(ratio, 1.0 + 1e-6);
        const Measured m = measure(r.samples, r.points, p.period), m0 = measure(reference.samples, reference.points, p.period);
        for (int a = 0; a < 3; ++a) {  // finite differences, as a drive sees them
            ASSERT_LE(m.max_velocity[a], p.limits.axis[a].max_velocity * (1 + 1e-6));
            ASSERT_LE(m.max_acceleration[a], p.limits.axis[a].max_acceleration * (1 + 1e-6));
            ASSERT_LE(m.max_jerk[a], p.limits.axis[a].max_jerk * (1 + 1e-6));
        }
        if (r.aborted) {  // stopped on the path, within the limits and the stop time; nothing after
            ++aborts;
            double widest = 0.0;
            for (const Block& b : blocks) widest = std::max(widest, b.tolerance);
            ASSERT_LE(m.max_contour_error, widest + std::sqrt(3.0) * p.limits.axis[0].max_acceleration * p.period * p.period / 8);
            ASSERT_EQ(r.samples.back().velocity, AxisVector::Zero());
            ASSERT_LE(r.longest_stop, stop_time(rate_limits(p), p.max_rate) + 2 * p.period);
            continue;
        }
        // The path does not depend on the rate: corner errors as at 100 %. After a rate change the
        // samples fall between the planned ones, and a chord between two samples lies within its
        // sagitta |a| dt^2 / 8 of the continuous path (at most 2.2 um here). So the two runs'
        // errors differ by the path's 1 % or that sagitta (scale 8, seed 6, program 841: a 0.013 mm
        // tolerance, 0.14 um apart).
        const double sagitta = std::sqrt(3.0) * p.limits.axis[0].max_acceleration * p.period * p.period / 8;
        ASSERT_EQ(m.corner_errors.size(), m0.corner_errors.size());
        for (std::size_t c = 0; c < m.corner_errors.size(); ++c) {
            ASSERT_LE(m.corner_errors[c], blocks[c].tolerance + sagitta);
            ASSERT_NEAR(m.corner_errors[c], m0.corner_errors[c], std::max(0.01 * blocks[c].tolerance, sagitta) + 1e-6);
        }
        ASSERT_EQ(m.end_position, blocks.back().target);
        if (r.longest_stop > 0.0) {
            ++holds;
            const double bound = stop_time(rate_limits(p), p.max_rate) + p.period;
            worst_stop_ratio = std::max(worst_stop_ratio, r.longest_stop / bound);
            ASSERT_LE(r.longest_stop, bound);
        }
    }
    EXPECT_GT(holds, 20);
    EXPECT_GT(aborts, 20);
    EXPECT_GT(worst, 0.95);  // the limits are reached, not only respected from afar
    std::printf("%d programs with rate changes: worst |v|,|a| / limit %.4f; %d holds, longest %.2f of the bound; %d aborts\n",
                programs, worst, holds, worst_stop_ratio, aborts);
}
