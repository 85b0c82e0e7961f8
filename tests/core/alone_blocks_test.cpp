// Short blocks between two stops (reversals, G61): each is planned alone, with the steps that make
// it fastest, not with the tolerance's dense regime (which no corner there needs). Measured on the
// samples: cycle time against the tolerance, limits, end.
#include "support/limits.hpp"
#include "support/reference.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

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
// period), and faster at each tolerance above 0.01 mm.
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
            EXPECT_LE(t.cycle_time, previous + p.period);
        }
        std::printf("tolerance %.3f mm: cycle time %.4f s\n", tolerance, t.cycle_time);
        previous = t.cycle_time;
    }
    EXPECT_LT(previous, 1.55);  // 0.1 mm: 1.538 s (1.850 s before)
}
