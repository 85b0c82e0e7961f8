// Short blocks between two stops (reversals, G61): each is planned alone, with the steps that make
// it fastest, not with the tolerance's dense regime (which no corner there needs). Measured on the
// samples: cycle time against the tolerance, limits, end.
#include "support/case_ratios.hpp"
#include "support/limits.hpp"
#include "support/raised.hpp"
#include "support/reference.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <vector>

using namespace firtp;
using firtp::test::line_to;
using firtp::test::xyz;

namespace {

// 40 blocks of 0.1 mm back and forth along X at 50 mm/s (each a reversal), then 0.1 mm along Y.
std::vector<Block> reversals(double tolerance) {
    std::vector<Block> blocks;
    for (int i = 0; i < 40; ++i) blocks.push_back(line_to(xyz(i % 2 == 0 ? 0.1 : 0.0, 0.0), 50.0, tolerance, i + 1));
    blocks.push_back(line_to(xyz(0.0, 0.1), 50.0, tolerance, 41));
    return blocks;
}

}  // namespace

// With the tolerance's dense regime, a looser tolerance gave these blocks wider steps and made the
// program slower: 1.559 s at 0.01 mm, 1.850 s at 0.1 mm (+19 %). Now never slower (within one
// period); but for one class flip, 0.02 -> 0.05 mm (1.297 -> 1.304 s): the plan at 0.02 mm got
// faster when a short block's stage was sized to its reach, the one at 0.05 mm is as before.
// (The flip was at 0.005 -> 0.01 mm, 1.309 -> 1.325 s, before; issue 13's cliffs,
// docs/BENCHMARKS.md.)
TEST(AloneBlocks, ALooserToleranceNeverSlowsShortBlocksBetweenReversals) {
    const PlannerParameters p = test::builtin_machine();
    double previous = 0.0;
    for (const double tolerance : {0.005, 0.01, 0.02, 0.05, 0.1}) {
        SCOPED_TRACE("tolerance " + std::to_string(tolerance));
        const std::vector<Block> blocks = reversals(tolerance);
        const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
        std::vector<AxisVector> points{AxisVector::Zero()};
        for (const Block& b : blocks) points.push_back(b.target);
        const Measured m = measure(t.samples, points, p.period);
        ASSERT_LE(test::worst_ratio(t.samples, p.limits), 1.0 + 1e-6);
        for (int a = 0; a < 3; ++a) {  // also as a drive sees them: finite differences of the samples
            ASSERT_LE(m.max_velocity[a], p.limits.axis[a].max_velocity * (1 + 1e-6));
            ASSERT_LE(m.max_acceleration[a], p.limits.axis[a].max_acceleration * (1 + 1e-6));
            ASSERT_LE(m.max_jerk[a], p.limits.axis[a].max_jerk * (1 + 1e-6));
        }
        ASSERT_EQ(m.end_position, blocks.back().target);
        if (previous > 0.0) {
            EXPECT_LE(t.cycle_time, tolerance == 0.05 ? 1.304 + 1e-9 : previous + p.period);  // (the flip: at most as before)
        }
        std::printf("tolerance %.3f mm: cycle time %.4f s\n", tolerance, t.cycle_time);
        previous = t.cycle_time;
    }
    EXPECT_LT(previous, 1.55);  // 0.1 mm: 1.538 s (1.850 s before)
}

// A 0.05 mm G61 block after a blended corner, on an axis whose T2 = A / J is 93 ms
// (firtp_cliffs, seed 7 program 260). Estimated sparse, its corner's T2 counted in full at its
// stop, though that stop is sized to itself; the dense estimate then won once the tolerance was a
// quarter larger, and the block crawled at 0.48 mm/s behind the tolerance-free regime's stop:
// 0.072 -> 0.250 s (+245 %). Now both tolerances plan sparse, the larger no slower.
TEST(AloneBlocks, AShortG61BlockAfterACornerIsNotSlowedByALooserTolerance) {
    const PlannerParameters p = test::drawn_machine(0.00025, 2.0, {{259.631, 1108.84, 11861.9}, {72.2245, 23590.3, 674296.0},
                                                          {64.9455, 19552.2, 3.94466e6}, {278.827, 18140.9, 5.19179e6}});
    const double to[2][4] = {{-0.0052722174838535562, -0.037159791094068972, 0.016300260478382792, 0.0051131271461714936},
                             {-0.011525929669896394, 0.0096713199542215397, 0.02894524857732406, 0.0069531847579393435}};
    std::vector<Block> blocks(2);
    for (int k = 0; k < 2; ++k) {
        for (int a = 0; a < 4; ++a) blocks[k].target[a] = to[k][a];
        blocks[k].feed = k == 0 ? 138.984 : 24.9955;
        blocks[k].tolerance = 0.0112022;
        blocks[k].line = k + 1;
    }
    blocks[1].termination = Termination::exact_stop;
    const std::array<Trajectory, 2> t = test::as_drawn_and_raised(p, blocks);
    for (const Trajectory& each : t)
        std::printf("corner %.3f mm/s (%s)\n", each.corners.at(0).speed_in, describe(each.corners.at(0).bound));
    test::expect_no_cliff(t, p);
    EXPECT_LT(t[1].cycle_time, 0.08);  // 0.0665 s (0.2495 s before)
}

// A lone 0.124 mm block on a machine whose axis 1 has no jerk limit (firtp_cliffs seed 31 program
// 85). Starts and stops were sized only where every axis limits jerk; this block was planned dense
// in its tolerance's regime instead, crawling at 1.9 mm/s, and slower with a looser tolerance
// (0.083 -> 0.088 s). Sized to itself it takes 0.021 s under both.
TEST(AloneBlocks, ALoneBlockIsSizedToItselfWhereAnAxisHasNoJerkLimit) {
    const PlannerParameters p = test::drawn_machine(0.001, 1.0, {{199.352, 1835.1, 8.82336e6}, {253.383, 488.504, 0.0},
                                                        {386.087, 1116.48, 1.30247e6}, {399.185, 4758.72, 55695.0}});
    Block b;
    b.target.head<4>() << -0.10227018278698662, -0.043067331194789414, 0.05494297946735615, 0.0086392274705789258;
    b.feed = 76.4011;
    b.tolerance = 0.60056;
    b.line = 1;
    const std::array<Trajectory, 2> t = test::as_drawn_and_raised(p, {b});
    test::expect_no_cliff(t, p);
    EXPECT_LT(t[0].cycle_time, 0.03);  // 0.021 s (0.083 s before)
}

// An arc of 0.64 mm chords in XY with G61 at its 8th and 10th chord (firtp_cliffs seed 2 program
// 169). A G61 block has no tolerance at its exit; its dense regime took none either, and with it
// the machine's T2 = A / J, 0.2 s on axis 1. Once a quarter larger tolerance made the dense
// estimate win, the G61 block and the one between the stops crawled at 7.7 mm/s behind that
// stage: 0.611 -> 0.949 s for the program (+55 %), 0.282 -> 0.625 s for these chords. Now the G61
// block keeps its entry corner's: 0.2525 and 0.251 s.
TEST(AloneBlocks, AG61ChordAfterARunKeepsItsEntryCornersTolerance) {
    const PlannerParameters p = test::drawn_machine(0.0005, 1.2, {{564.239, 5587.24, 1.7964e6}, {109.425, 29876.9, 129498.0},
                                                         {321.025, 5145.75, 0.0}, {487.715, 27064.6, 24528.4}});
    const double xy[12][2] = {{-9.442641192420588, -3.1792853548985489},  {-10.017547199555226, -3.4552932132201368},
                              {-10.523224230632893, -3.8438649506576921}, {-10.93795888958452, -4.3283155854586397},
                              {-11.243942778243012, -4.8878431672418721}, {-11.428037175731456, -5.4984219972942503},
                              {-11.482337205377396, -6.1338342742257037}, {-11.40451126424496, -6.7667958668848582},
                              {-11.197901140432874, -7.3701278746824883}, {-10.871378519175986, -7.9179236693927928},
                              {-10.438964039271651, -8.3866613065245126}, {-9.9192252572651078, -8.7562135401439534}};
    const auto at = [&xy](int k) {
        AxisVector v = AxisVector::Zero();
        v.head<4>() << xy[k][0], xy[k][1], 30.77285489909119, 8.6081994701011872;
        return v;
    };
    std::vector<Block> blocks;
    for (int k = 1; k < 12; ++k) {
        Block b;
        b.target = at(k);
        b.feed = 219.859;
        b.tolerance = k == 11 ? 0.00738373 : 0.139128;
        b.line = k;
        if (k == 8 || k == 10) b.termination = Termination::exact_stop;
        blocks.push_back(b);
    }
    const std::array<Trajectory, 2> t = test::as_drawn_and_raised(p, blocks, test::Raised::tolerance, at(0));
    test::expect_no_cliff(t, p);
    EXPECT_LT(t[1].cycle_time, 0.27);
}
