// smoothing_limits (parameters.hpp): the accelerations smoothing at the limits plans with.
// - never above the machine's, and every step's kernel within its acceleration and jerk limits;
// - no step's kernel wider than with the machine's own accelerations (T2 = max A / J);
// - acceleration no step can use changes nothing: with T2 at its longest useful value
//   (max sqrt(2 V / J)), axes at J T2 or at twice that plan a program in the same samples, to rounding (before,
//   more acceleration lengthened T2: one cause of firtp_cliffs' slower cases).
#include "support/random_machine.hpp"

#include <firtp/kernel.hpp>
#include <firtp/parameters.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

using namespace firtp;

namespace {

TEST(SmoothingLimits, StepsStayWithinTheLimitsAndNoStepGetsWider) {
    std::mt19937_64 rng(41 + test::random_seed_offset());
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int narrower = 0;
    for (int k = 0; k < test::random_scaled(20000); ++k) {
        const MachineLimits machine = test::random_machine(rng).limits;
        const MachineLimits planned = smoothing_limits(machine);
        AxisVector dv = AxisVector::Zero();  // up to a reversal at full speed on every axis
        for (int a = 0; a < machine.axes; ++a) dv[a] = 2.0 * machine.axis[a].max_velocity * unit(rng);
        const Kernel wide = step_kernel(machine, dv), kernel = step_kernel(planned, dv);
        ASSERT_LE(kernel.width(), wide.width() * (1.0 + 1e-12)) << "machine " << k;
        narrower += kernel.width() < wide.width() * (1.0 - 1e-9);
        for (int a = 0; a < machine.axes; ++a) {
            const AxisLimits& l = machine.axis[a];
            ASSERT_LE(planned.axis[a].max_acceleration, l.max_acceleration) << "machine " << k << " axis " << a;
            const double d = std::abs(dv[a]);
            if (d == 0.0) continue;
            ASSERT_LE(d * kernel.peak_acceleration(), l.max_acceleration * (1.0 + 1e-9)) << "machine " << k << " axis " << a;
            if (l.max_jerk > 0.0) {
                ASSERT_LE(d * kernel.peak_jerk(), l.max_jerk * (1.0 + 1e-9)) << "machine " << k << " axis " << a;
            }
        }
    }
    EXPECT_GT(narrower, 0);  // the rule does something on these machines
}

TEST(SmoothingLimits, AccelerationNoStepCanUseChangesNothing) {
    std::mt19937_64 rng(43 + test::random_seed_offset());
    int compared = 0;
    for (int k = 0; k < test::random_scaled(60); ++k) {
        const test::RandomCase c = test::random_case(rng);
        // T2 at its longest useful value (max sqrt(2 V / J)); every jerk-limited axis at J T2, or twice that.
        double t2 = 0.0;
        for (int a = 0; a < c.parameters.limits.axes; ++a) {
            const AxisLimits& l = c.parameters.limits.axis[a];
            if (l.max_jerk > 0.0) t2 = std::max(t2, std::sqrt(2.0 * l.max_velocity / l.max_jerk));
        }
        PlannerParameters enough = c.parameters, more = c.parameters;
        for (int a = 0; a < enough.limits.axes; ++a) {
            const double j = c.parameters.limits.axis[a].max_jerk;
            if (!(j > 0.0)) continue;
            enough.limits.axis[a].max_acceleration = j * t2;
            more.limits.axis[a].max_acceleration = 2.0 * j * t2;
        }
        const Trajectory a = plan_trajectory(enough, AxisVector::Zero(), c.blocks);
        const Trajectory b = plan_trajectory(more, AxisVector::Zero(), c.blocks);
        ASSERT_EQ(a.samples.size(), b.samples.size()) << "program " << k;
        for (std::size_t i = 0; i < a.samples.size(); ++i)
            ASSERT_LT((a.samples[i].position - b.samples[i].position).norm(), 1e-9) << "program " << k << " sample " << i;
        ++compared;
    }
    EXPECT_EQ(compared, test::random_scaled(60));
}

}  // namespace
