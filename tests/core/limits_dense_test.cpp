// Axis limits at every sample, overlaps included; dense paths (many blocks in one filter window)
// within tolerance without the feed collapsing. Measured on the output.
#include "support/case_ratios.hpp"
#include "support/limits.hpp"
#include "support/raised.hpp"
#include "support/reference.hpp"
#include "support/separation.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <limits>
#include <random>

using namespace firtp;
using firtp::test::line_to;
using firtp::test::xyz;

TEST(AxisLimits, HoldAtEverySampleOverRandomProgramsWithOverlapsAndShortFilters) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst_difference_jerk = 0.0, worst_difference_acceleration = 0.0;
    for (int k = 0; k < 300; ++k) {
        PlannerParameters p;
        p.period = 0.001;
        // Limits and filters drawn independently: often the filters are too short for the limits.
        p.limits = test::uniform_limits(100 + 300 * unit(rng), 500 + 9500 * unit(rng), 1e4 + 4e5 * unit(rng));
        p.fixed_chain = true;
        p.filters = test::chain_of({0.01 + 0.1 * unit(rng), 0.005 + 0.04 * unit(rng)});
        if (p.filters.T[1] > p.filters.T[0]) std::swap(p.filters.T[0], p.filters.T[1]);
        std::vector<Block> blocks;
        AxisVector at = AxisVector::Zero();
        const int n = 2 + static_cast<int>(rng() % 8);
        for (int i = 0; i < n; ++i) {
            const AxisVector d = xyz(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
            at += d * (0.2 + 40 * unit(rng) * unit(rng));
            blocks.push_back(line_to(at, 20 + 380 * unit(rng), 0.001 + unit(rng), i + 1));
        }
        const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
        std::vector<AxisVector> points{AxisVector::Zero()};
        for (const Block& b : blocks) points.push_back(b.target);
        const Measured m = measure(t.samples, points, p.period);
        SCOPED_TRACE("program " + std::to_string(k));
        ASSERT_LE(test::worst_ratio(t.samples, p.limits), 1.0 + 1e-6);  // what the planner guarantees
        for (int a = 0; a < 3; ++a) {  // finite differences of the positions, as a drive sees them
            ASSERT_LE(m.max_velocity[a], p.limits.axis[a].max_velocity * (1 + 1e-6));
            ASSERT_LE(m.max_acceleration[a], p.limits.axis[a].max_acceleration * (1 + 1e-6));
            worst_difference_acceleration =
                std::max(worst_difference_acceleration, m.max_acceleration[a] / p.limits.axis[a].max_acceleration);
            worst_difference_jerk = std::max(worst_difference_jerk, m.max_jerk[a] / p.limits.axis[a].max_jerk);
            ASSERT_LE(m.max_jerk[a], p.limits.axis[a].max_jerk * (1 + 1e-6));
        }
        ASSERT_EQ(m.end_position, blocks.back().target);
    }
    std::printf("finite differences of positions / limit, largest: acceleration %.5f, jerk %.4f\n",
                worst_difference_acceleration, worst_difference_jerk);
}

TEST(AxisLimits, ReversalWithFullOverlapWouldDoubleTheAccelerationAndIsHeldToTheLimit) {
    PlannerParameters p;
    p.fixed_chain = true;
    p.filters = test::chain_of({0.06, 0.02});
    p.limits = test::uniform_limits(300, 5000, 5e5);  // T1 = v / a: one block alone reaches a = F / T1 = 5000 at 300 mm/s
    const std::vector<Block> blocks{line_to(xyz(40, 0), 300, 5.0, 1), line_to(xyz(0, 0), 300, 5.0, 2)};
    const Trajectory limited = plan_trajectory(p, AxisVector::Zero(), blocks);
    p.limits = MachineLimits{};
    const Trajectory free = plan_trajectory(p, AxisVector::Zero(), blocks);
    double a_free = 0, a_limited = 0;
    for (const AxisState& s : free.samples) a_free = std::max(a_free, std::abs(s.acceleration[0]));
    for (const AxisState& s : limited.samples) a_limited = std::max(a_limited, std::abs(s.acceleration[0]));
    EXPECT_GT(a_free, 7000.0);           // the overlapped reversal adds the two blocks' accelerations
    // The plan keeps 20 % of the acceleration for override and hold ramps (rate_reserve).
    EXPECT_LE(a_limited, 4000.0 * (1 + 1e-9));
    EXPECT_GT(a_limited, 3920.0);        // and the rest is used, not wasted
}

TEST(DensePaths, ChordedCircleKeepsTheFeedAndTheTolerance) {
    // R 20 mm in 0.2 mm chords (628 blocks, 125 in one 0.11 s window at 50 mm/s). The filters'
    // radial shrink F^2 (T1^2 + T2^2) / (24 R) = 0.032 mm is within the 0.05 mm tolerance.
    PlannerParameters p;
    p.fixed_chain = true;
    p.filters = test::chain_of({0.06, 0.05});
    p.tolerance_meaning = ToleranceMeaning::contour;
    const double R = 20.0, feed = 50.0, tolerance = 0.05;
    const int n = static_cast<int>(std::ceil(2 * std::numbers::pi * R / 0.2));
    std::vector<Block> blocks;
    for (int i = 1; i <= n; ++i) {
        const double phi = 2 * std::numbers::pi * i / n;
        blocks.push_back(line_to(xyz(R * std::sin(phi), R - R * std::cos(phi)), feed, tolerance, i));
    }
    const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
    std::vector<AxisVector> points{AxisVector::Zero()};
    for (const Block& b : blocks) points.push_back(b.target);
    const Measured m = measure(t.samples, points, p.period);
    EXPECT_LE(m.max_contour_error, tolerance);
    // Average speed between the first and the last quarter of the circle: the steady shrink is
    // within tolerance, so the feed must stay (issue 4 asks for 90 %; measured 99.8 %).
    const std::size_t a = t.samples.size() / 4, b = 3 * t.samples.size() / 4;
    double travelled = 0;
    for (std::size_t i = a; i < b; ++i) travelled += (t.samples[i + 1].position - t.samples[i].position).norm();
    const double average = travelled / (t.samples[b].time - t.samples[a].time);
    std::printf("chorded circle: average %.1f mm/s of %.0f programmed\n", average, feed);
    EXPECT_GT(average, 0.9 * feed) << "average " << average << " mm/s";
    EXPECT_EQ(m.end_position, blocks.back().target);
}

TEST(DensePaths, ZigZagFinishingPassHoldsEveryCorner) {
    PlannerParameters p;
    p.fixed_chain = true;
    p.filters = test::chain_of({0.05, 0.02});
    std::vector<Block> blocks;
    const double tolerance = 0.01;
    for (int i = 1; i <= 400; ++i) blocks.push_back(line_to(xyz(0.25 * i, (i % 2) * 0.4), 100.0, tolerance, i));
    const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
    std::vector<AxisVector> points{AxisVector::Zero()};
    for (const Block& b : blocks) points.push_back(b.target);
    const Measured m = measure(t.samples, points, p.period);
    ASSERT_EQ(m.corner_errors.size(), blocks.size() - 1);
    for (std::size_t c = 0; c < m.corner_errors.size(); ++c) ASSERT_LE(m.corner_errors[c], tolerance) << "corner " << c;
    EXPECT_EQ(m.end_position, blocks.back().target);
}

TEST(DensePaths, RetractAndPlungeBeforeCornersDoNotHideThem) {
    // Up and down the same line returns to the start; the corner tracking must follow the tool
    // past it (it once stayed behind and a 90 deg corner was cut by 0.52 mm at 0.02 mm tolerance).
    for (bool limited : {false, true}) {
        PlannerParameters p;
        p.fixed_chain = true;
        p.filters = test::chain_of({0.06, 0.05});
        if (limited) p.limits = test::uniform_limits(300, 5000, 1e5);
        const double tolerance = 0.02;
        const std::vector<Block> blocks{line_to(xyz(0, 0, 1), 300, tolerance, 3), line_to(xyz(0, 0, 0), 5, tolerance, 4),
                                        line_to(xyz(20, 0, 0), 40, tolerance, 5), line_to(xyz(20, 20, 0), 40, tolerance, 6),
                                        line_to(xyz(0, 20, 0), 40, tolerance, 7)};
        const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
        std::vector<AxisVector> points{AxisVector::Zero()};
        for (const Block& b : blocks) points.push_back(b.target);
        const Measured m = measure(t.samples, points, p.period);
        ASSERT_EQ(m.corner_errors.size(), 4u);
        for (std::size_t c = 0; c < m.corner_errors.size(); ++c)
            EXPECT_LE(m.corner_errors[c], tolerance) << "corner " << c << (limited ? " with limits" : "");
        EXPECT_EQ(m.end_position, xyz(0, 20, 0));
    }
}

TEST(DensePaths, PathsPassingBackNearThemselvesDoNotLoseTheToolOrTheFeed) {
    // The stretch of firtp_plan_stream's random program (seed 1: chords of 0.1-2 mm turning up to
    // 90 degrees, turned straight back at 200 mm from the origin) where the tool used to be lost:
    // the walk passes back over earlier junctions, the nearest-segment tracking took the tool for
    // being elsewhere, and the planner committed unchecked blocks, 0.97 mm off the path, then
    // crawled at 0.1 % of the feed. Junctions are now told apart by time as well as by distance.
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), turn(0.0, std::numbers::pi / 2), length(0.1, 2.0),
        feed(100.0, 300.0), tolerance(0.01, 0.05);
    AxisVector at = AxisVector::Zero(), direction = xyz(1, 0, 0), start = at;
    std::vector<Block> blocks;
    constexpr long skipped = 321000, planned = 1000;
    for (long i = 0; i < skipped + planned; ++i) {
        AxisVector axis = AxisVector::Zero();
        for (int a = 0; a < 3; ++a) axis[a] = unit(rng);  // in order: arguments would be drawn in any order
        axis -= axis.dot(direction) * direction;
        if (axis.norm() > 1e-9) {
            const double angle = turn(rng);
            direction = (std::cos(angle) * direction + std::sin(angle) * axis.normalized()).normalized();
        }
        if (at.norm() > 200.0 && direction.dot(at) > 0.0) direction = -direction;
        at += direction * length(rng);
        const double f = feed(rng), tol = tolerance(rng);  // drawn in this order, as the benchmark does
        if (i == skipped - 1) start = at;
        if (i >= skipped) blocks.push_back(line_to(at, f, tol, i + 1));
    }
    PlannerParameters p;
    p.fixed_chain = true;
    p.filters = test::chain_of({0.06, 0.05});
    p.limits = test::uniform_limits(300, 5000, 1e5);
    const Trajectory t = plan_trajectory(p, start, blocks);

    std::vector<AxisVector> points{start};
    double bound = 0.0;  // every block an exact stop at 80 % of its feed (short pulses double the jerk)
    for (const Block& b : blocks) {
        bound += (b.target - points.back()).norm() / (0.8 * b.feed) + p.filters.delay() + 2 * p.period;
        points.push_back(b.target);
    }
    // Distance of every sample from the programmed path within 50 blocks of the one it executes
    // (no attribution to junctions needed; at least the distance from the whole path).
    double off_path = 0.0;
    std::int64_t executing = 0;  // index of the block executing (line 0: at rest, before or after)
    for (const AxisState& s : t.samples) {
        if (s.line > 0) executing = s.line - skipped - 1;
        const auto k0 = static_cast<std::size_t>(std::clamp<std::int64_t>(executing - 50, 0, planned));
        const auto k1 = static_cast<std::size_t>(std::clamp<std::int64_t>(executing + 51, 0, planned));
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = k0; k < k1; ++k)
            nearest = std::min(nearest, test::segment_distance(s.position, s.position, points[k], points[k + 1]));
        off_path = std::max(off_path, nearest);
    }
    std::printf("random walk passing back over itself: %.1f s (exact stops: %.1f s), %.4f mm off the path\n",
                t.cycle_time, bound, off_path);
    EXPECT_LE(off_path, 0.05);  // the largest tolerance of the program
    EXPECT_LT(t.cycle_time, bound);
    EXPECT_EQ(t.samples.back().position, blocks.back().target);
}

// A 25 mm block between two smooth corners, the next block 0.86 mm long and ending in G61
// (firtp_cliffs seed 1 program 127, its first five blocks). With the velocity limits a quarter
// higher the long block became short and, between smooth corners, dense: held at one speed, the
// speed at which the 0.86 mm block could stop, 0.408 -> 0.540 s over it; these five blocks took
// 0.847 -> 1.026 s (+21 %). A run that a stop ends one block later leaves the class to the
// estimates: 0.847 -> 0.8535 s. (The 0.8 % left is a cliff not fixed: issue 13.)
TEST(DensePaths, ALongBlockIsNotHeldToOneSpeedWhereAStopEndsTheRunAfterIt) {
    const double to[5][2] = {{0.54554649868951288, -1.7020877046202383},
                             {-5.0196404102922063, -5.2219484509830352},
                             {-25.520809601907871, -19.64323840802243},
                             {-26.230198428428462, -20.130861207138555},
                             {-26.949972888194431, -20.60301926169095}};
    const double tolerance[5] = {0.0979197, 0.146933, 0.0979197, 0.0979197, 0.0979197};
    std::vector<Block> blocks(5);
    for (int k = 0; k < 5; ++k) {
        blocks[k].target = xyz(to[k][0], to[k][1]);
        blocks[k].feed = 209.97;
        blocks[k].tolerance = tolerance[k];
        blocks[k].line = k + 1;
    }
    blocks[3].termination = Termination::exact_stop;
    const PlannerParameters p = test::drawn_machine(0.0005, 2.0, {{114.292, 24620.9, 19065.0}, {99.3335, 1334.06, 2.83869e6}});
    const std::array<Trajectory, 2> t = test::as_drawn_and_raised(p, blocks, test::Raised::velocity);
    EXPECT_LE(t[1].cycle_time, t[0].cycle_time * 1.01);
}

// A 0.02 mm block, then nine of 1.54 mm along a gentle curve (firtp_cliffs seed 31 program 61).
// With every tolerance a quarter larger the first corner became smooth, and a block between two
// smooth corners was dense whatever the estimates: the 1.54 mm block ran at 6.4 mm/s, the speed
// the 0.02 mm block allows its junction, instead of reaching 43 mm/s: 0.327 -> 0.376 s. Now the
// estimates decide there too (a tie goes dense): 0.327 -> 0.331 s.
TEST(DensePaths, BetweenSmoothCornersTheEstimatesStillDecide) {
    const double xy[10][2] = {{0.015893960214094057, -0.012597961798684247}, {1.2693329872277417, -0.91178454796857444},
                              {2.6030903579002542, -1.6868569235345721},    {4.0049164490867284, -2.330696593994249},
                              {5.4619364743310106, -2.8373903449187381},    {6.9607687297218233, -3.2022845506672866},
                              {8.4876474954291012, -3.4220279146649233},    {10.028549464156372, -3.4946022487038384},
                              {11.569322535352823, -3.4193410085822826},    {13.095815792300774, -3.1969354158441288}};
    const PlannerParameters p = test::drawn_machine(0.001, 2.0, {{58.7832, 16297.5, 1.39418e7}, {123.372, 1463.16, 1.13934e7},
                                                               {335.425, 7458.82, 16113.1}, {72.9609, 447.293, 0.0},
                                                               {106.065, 566.253, 5.58559e6}});
    std::vector<Block> blocks(10);
    for (int k = 0; k < 10; ++k) {
        blocks[k].target = AxisVector::Zero();
        blocks[k].target.head<5>() << xy[k][0], xy[k][1], 0.0043179550020155163, -0.003433904290035753, -0.00079099788491982892;
        blocks[k].feed = 52.9531;
        blocks[k].tolerance = k == 6 ? 0.00612523 : k == 9 ? 0.004382 : 0.06318;
        blocks[k].line = k + 1;
    }
    const std::array<Trajectory, 2> t = test::as_drawn_and_raised(p, blocks);
    EXPECT_LE(t[1].cycle_time, t[0].cycle_time * 1.02);  // (0.331 against 0.327 s: a cliff of 1.2 % not fixed, issue 13)
}
