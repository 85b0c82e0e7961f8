// Corners of 120 degrees and more are passed with the blocks' pulses overlapping (the paper's Tk,
// lookahead.hpp Segment::overlap): the tool turns before it reaches the corner point, within the
// tolerance, at the feed. Measured on the samples: the corner errors, the limits (also in finite
// differences), the exact end, and a cycle time no pass at the feed along the programmed path has.
#include "support/limits.hpp"
#include "support/random_machine.hpp"
#include "support/rate_run.hpp"
#include "support/within.hpp"

#include <firtp/measure.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace firtp;

namespace {

// A zig-zag of `legs` legs of `length` turning by `turn` radians at each end, in the plane of axes
// 0 and 1, at `feed` with G64 P`tolerance`; z rises `rise` a leg.
std::vector<Block> zig_zag(int legs, double length, double turn, double feed, double tolerance, double rise = 0.0) {
    const double half = 0.5 * (M_PI - turn);  // each leg's angle off the zig-zag's axis
    std::vector<Block> program;
    AxisVector at = AxisVector::Zero();
    for (int k = 0; k < legs; ++k) {
        at[0] += (k % 2 == 0 ? 1.0 : -1.0) * length * std::cos(half);
        at[1] += length * std::sin(half);
        at[2] += rise;
        Block b;
        b.target = at;
        b.feed = feed;
        b.tolerance = tolerance;
        b.line = k + 1;
        program.push_back(b);
    }
    return program;
}

double path_length(const std::vector<Block>& program) {
    double length = 0.0;
    AxisVector at = AxisVector::Zero();
    for (const Block& b : program) length += (b.target - at).norm(), at = b.target;
    return length;
}

// The machine of examples/linuxcnc/compare.py at jerk 5e6.
PlannerParameters compare_machine() {
    PlannerParameters p = test::builtin_machine();
    p.limits = test::uniform_limits(300.0, 5000.0, 5e6);
    return p;
}

}  // namespace

// pcb2gcode's slot in the drill file: 2 mm legs at F100 in/min (42.3 mm/s) turning by 174 degrees,
// G64 P0.508. Passed as one step at the feed each turn used 0.18 mm of the 0.508 and the program
// took its length / feed; overlapped, each turn uses the tolerance and takes Tk less.
TEST(OverlappedCorner, ZigZagSlotCutsItsTurnsWithinTheTolerance) {
    const PlannerParameters p = compare_machine();
    const double feed = 2540.0 / 60.0, tolerance = 0.508;
    const std::vector<Block> program = zig_zag(40, 2.0, 174.0 * M_PI / 180.0, feed, tolerance);
    const test::RateRun r = test::run_with_rates(p, program, {});
    test::expect_within(r, program, p);
    std::vector<AxisVector> points{AxisVector::Zero()};
    for (const Block& b : program) points.push_back(b.target);
    const Measured m = measure(r.samples, points, p.period);
    const double least = *std::min_element(m.corner_errors.begin(), m.corner_errors.end());
    const double at_feed = path_length(program) / feed;
    std::printf("cycle %.4f s (length / feed %.4f s), corner errors %.4f-%.4f mm of %.3f, %llu overlapped\n", m.cycle_time,
                at_feed, least, m.max_corner_error, tolerance, static_cast<unsigned long long>(r.stats.overlapped));
    EXPECT_GT(least, 0.9 * tolerance);          // each turn uses its tolerance
    EXPECT_LT(m.cycle_time, 0.8 * at_feed);     // only a shorter path than the program's is that fast
    EXPECT_EQ(r.stats.overlapped, program.size() - 1);
}

// Once a turn's first step has started, the tool runs on to its second (Tk later) before a hold
// can brake: at a low override Tk = overlap / V would grow without end (0.24 s at 5 %, twice the
// bound). The overlap shrinks there instead (Segment::overlap_tk): holds at every moment of the
// slot, at overrides from 1 % to 120 %, on both jerk limits, come to rest within hold_time_bound().
TEST(OverlappedCorner, HoldsAtAnyOverrideStopWithinTheBound) {
    for (double jerk : {5e6, 1e5})
        for (double feed : {2540.0 / 60.0, 10.0})
            for (double rate : {0.01, 0.05, 0.2, 1.0, 1.2}) {
                PlannerParameters p = compare_machine();
                p.limits = test::uniform_limits(300.0, 5000.0, jerk);
                p.max_rate = 1.2;
                const std::vector<Block> program = zig_zag(6, 2.0, 174.0 * M_PI / 180.0, feed, 0.508);
                const int duration = static_cast<int>(path_length(program) / (feed * rate) / p.period);
                double worst = 0.0;
                std::uint64_t overlapped = 0;
                for (int tick = 20; tick < duration; tick += std::max(1, duration / 80)) {
                    const test::RateRun r = test::run_with_rates(p, program, {{1, rate}, {tick, 0.0}, {tick + 3000, 1.0}});
                    ASSERT_TRUE(r.ended);
                    worst = std::max(worst, r.longest_stop);
                    overlapped += r.stats.overlapped;
                }
                SCOPED_TRACE("jerk " + std::to_string(jerk) + ", feed " + std::to_string(feed) + ", rate " + std::to_string(rate));
                EXPECT_LE(worst, hold_time_bound(p) + 2 * p.period);
                if (jerk == 5e6 || feed == 10.0) {  // (at 1e5 and F100 in/min the turns are bound by the tolerance)
                    EXPECT_GT(overlapped, 0u);
                }
            }
}

// Turns of less than 120 degrees are not overlapped: the leg across them would be faster than
// the feed.
TEST(OverlappedCorner, TurnsBelow120DegreesAreOneStep) {
    const PlannerParameters p = compare_machine();
    const std::vector<Block> program = zig_zag(20, 5.0, 110.0 * M_PI / 180.0, 40.0, 0.5);
    const test::RateRun r = test::run_with_rates(p, program, {});
    test::expect_within(r, program, p);
    EXPECT_EQ(r.stats.overlapped, 0u);
}

// Random zig-zags on random machines (support/random_machine.hpp): legs of 0.3-30 mm turning by
// 120-179.5 degrees, feeds of 1-300 (under 100 s a program), tolerances 0.01-1 mm, every other run
// with overrides up to the machine's highest and holds. Within the limits and tolerances, and
// overlapped where nothing binds but the feed.
TEST(OverlappedCorner, RandomZigZagsOnRandomMachines) {
    std::mt19937_64 rng(2026 + test::random_seed_offset());
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int programs = test::random_scaled(120);
    std::uint64_t overlapped = 0, corners = 0;
    for (int k = 0; k < programs; ++k) {
        PlannerParameters p = test::random_machine(rng);
        std::vector<Block> program;
        for (;;) {  // drawn again until corners two legs apart stay apart (the measurement follows the path)
            const double turn = (120.0 + 59.5 * unit(rng)) * M_PI / 180.0, length = test::log_uniform(rng, 0.3, 30.0);
            const double feed = test::log_uniform(rng, 1.0, 300.0), tolerance = test::log_uniform(rng, 0.01, 1.0);
            const double rise = p.limits.axes >= 3 && unit(rng) < 0.5 ? 0.1 * length : 0.0;
            program = zig_zag(4 + static_cast<int>(rng() % 30), length, turn, feed, tolerance, rise);
            std::vector<AxisVector> points{AxisVector::Zero()};
            for (const Block& b : program) points.push_back(b.target);
            if (path_length(program) / feed < 100.0 && test::well_separated(points, 3.0 * tolerance + feed * p.max_rate * p.period)) break;
        }
        std::vector<std::pair<int, double>> rates;
        if (k % 2 == 1) {
            const double estimate = path_length(program) / program.front().feed;
            int tick = 0;
            for (int e = 0; e < 4; ++e) {
                tick += 1 + static_cast<int>(unit(rng) * 0.3 * estimate / p.period);
                rates.emplace_back(tick, unit(rng) < 0.3 ? 0.0 : p.max_rate * (0.1 + 0.9 * unit(rng)));
            }
            rates.emplace_back(tick + 1 + static_cast<int>(unit(rng) * 0.3 * estimate / p.period), 1.0);
        }
        SCOPED_TRACE("program " + std::to_string(k));
        const test::RateRun r = test::run_with_rates(p, program, rates, static_cast<std::int64_t>(400.0 / p.period));
        test::expect_within_random(r, program, p);
        EXPECT_LE(r.longest_stop, hold_time_bound(p) + 2 * p.period);  // a hold after a turn's first step too
        overlapped += r.stats.overlapped;
        corners += program.size() - 1;
    }
    std::printf("%d zig-zags: %llu of %llu corners overlapped\n", programs, static_cast<unsigned long long>(overlapped),
                static_cast<unsigned long long>(corners));
    EXPECT_GT(overlapped, corners / 10);  // the overlap is what this measures
}
