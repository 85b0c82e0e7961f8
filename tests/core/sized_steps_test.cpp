// Starts and stops sized to themselves (sized_kernel, kernel.hpp): the kernel, then what it gives
// a program, measured on the samples: a rest-to-rest move in the jerk-limited time, limits held.
#include "support/limits.hpp"
#include "support/reference.hpp"

#include <firtp/kernel.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace firtp;
using firtp::test::line_to;
using firtp::test::xyz;

namespace {

// Every two-stage kernel T1 >= T2 with T1 >= v alpha (acceleration) and T1 T2 >= v beta (jerk) is
// at least as wide as sized_kernel's, which meets both: 20,000 random steps against a scan of T1.
TEST(SizedKernel, IsTheNarrowestTwoStageKernelWithinBothLimits) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> log10(-3.0, 3.0);
    for (int k = 0; k < 20000; ++k) {
        const double v = std::pow(10.0, log10(rng)), alpha = 1e-3 * std::pow(10.0, log10(rng)), beta = 1e-5 * std::pow(10.0, log10(rng));
        const Kernel sized = sized_kernel(v, alpha, beta);
        ASSERT_GE(sized.a, v * alpha * (1.0 - 1e-12)) << k;          // acceleration v / T1 <= 1 / alpha
        ASSERT_GE(sized.a * sized.b, v * beta * (1.0 - 1e-12)) << k;  // jerk v / (T1 T2) <= 1 / beta
        ASSERT_GE(sized.a, sized.b) << k;
        // One of the two limits is reached: nothing to spare.
        ASSERT_TRUE(std::abs(sized.a - v * alpha) <= 1e-12 * sized.a || std::abs(sized.a - sized.b) <= 1e-12 * sized.a) << k;
        const double lo = std::max(v * alpha, std::sqrt(v * beta));
        for (int m = 0; m <= 200; ++m) {  // T1 from the bound to 100 x it, T2 the least the jerk allows
            const double t1 = lo * std::pow(100.0, m / 200.0), t2 = std::min(t1, v * beta / t1);
            if (t1 * t2 < v * beta * (1.0 - 1e-12)) continue;  // (t2 capped at t1 cannot keep the jerk)
            ASSERT_GE(t1 + t2, sized.width() * (1.0 - 1e-12)) << k << " " << m;
        }
        // Never wider than the shared-stage kernel two_stage(v alpha, T2) where T2 keeps that jerk.
        const double t2_machine = beta / alpha * std::pow(10.0, std::abs(log10(rng)) / 3.0);
        ASSERT_LE(sized.width(), two_stage(v * alpha, t2_machine).width() * (1.0 + 1e-12)) << k;
    }
}

Measured measured(const PlannerParameters& p, const std::vector<Block>& blocks, const Trajectory& t) {
    std::vector<AxisVector> points{AxisVector::Zero()};
    for (const Block& b : blocks) points.push_back(b.target);
    return measure(t.samples, points, p.period);
}

void expect_within_limits(const PlannerParameters& p, const Trajectory& t, const Measured& m, const Block& last) {
    EXPECT_LE(test::worst_ratio(t.samples, p.limits), 1.0 + 1e-6);
    for (int a = 0; a < 3; ++a) {  // also as a drive sees them: 1 ms differences of the samples
        EXPECT_LE(m.max_velocity[a], p.limits.axis[a].max_velocity * (1 + 1e-6));
        EXPECT_LE(m.max_acceleration[a], p.limits.axis[a].max_acceleration * (1 + 1e-6));
        EXPECT_LE(m.max_jerk[a], p.limits.axis[a].max_jerk * (1 + 1e-6));
    }
    EXPECT_EQ(m.end_position, last.target);
}

// A short move from rest to rest at the jerk limit alone takes (32 d / J)^(1/3): 68.4 ms for 1 mm
// at 1e5 mm/s^3 (83 ms before, planned as a dense block alone). The samples end on the first
// period after the motion.
TEST(SizedSteps, AShortMoveTakesTheJerkLimitedRestToRestTime) {
    const PlannerParameters p = test::builtin_machine();
    for (const double d : {0.05, 0.2, 1.0, 2.0}) {
        SCOPED_TRACE("length " + std::to_string(d));
        const std::vector<Block> blocks{line_to(xyz(d, 0.0), 300.0, 0.05, 1)};
        const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
        const Measured m = measured(p, blocks, t);
        expect_within_limits(p, t, m, blocks.back());
        const double least = std::cbrt(32.0 * d / 1e5);
        EXPECT_GE(t.cycle_time, least - 1e-9);
        EXPECT_LE(t.cycle_time, least + 2.0 * p.period);
        std::printf("%.2f mm: cycle %.4f s, jerk-limited %.4f s, peak %.0f mm/s^2\n", d, t.cycle_time, least, m.max_acceleration[0]);
    }
}

// A long move whose speed change is below A^2 / J (250 mm/s here): each end is the S-curve of its
// step alone, 2 sqrt(F / J) (63.2 ms at F100), where the machine's shared jerk stage made it
// F / A + A / J (70 ms). Also along a diagonal, where each axis carries F / sqrt(2).
TEST(SizedSteps, ALongMoveStartsAndStopsOnItsOwnSCurve) {
    const PlannerParameters p = test::builtin_machine();
    for (const AxisVector& to : {xyz(20.0, 0.0), xyz(20.0, 20.0)}) {
        const std::vector<Block> blocks{line_to(to, 100.0, 0.05, 1)};
        const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
        const Measured m = measured(p, blocks, t);
        expect_within_limits(p, t, m, blocks.back());
        const double axis_dv = 100.0 * to.x() / to.norm();  // the most loaded axis' step
        const double expected = to.norm() / 100.0 + 2.0 * std::sqrt(axis_dv / 1e5);
        EXPECT_NEAR(t.cycle_time, expected, 1.0 * p.period) << to.transpose();
        EXPECT_GE(m.max_acceleration[0], 0.95 * std::sqrt(1e5 * axis_dv));  // the triangle's peak: sqrt(J dV)
    }
}

}  // namespace
