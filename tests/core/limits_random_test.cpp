// Seeded randomized suite of smoothing at the limits (support/random_machine.hpp: random machines
// with per-axis v, a, j, and random programs). Measured on the samples, never asserted:
// - every blended corner within its tolerance (the path straight from sample to sample),
// - axis velocity, acceleration and jerk within the limits, as the chain's values at the samples
//   and as finite differences of the positions, at the period and at 1 ms,
// - the end exactly on the last point, at rest, no NaN;
// and from the planner: nothing refused, no leg plan that failed to cover its block.
// FIRTP_RANDOM_SCALE multiplies the counts for soak runs (ctest -L soak).
#include "support/case_ratios.hpp"
#include "support/random_machine.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using namespace firtp;

namespace {

struct Worst {
    double corner = 0.0, velocity = 0.0, acceleration = 0.0, jerk = 0.0;
    std::size_t programs = 0, blocks = 0, corners = 0;
};

void expect_within(const test::RandomCase& c, const Trajectory& t, Worst& worst) {
    const PlannerParameters& p = c.parameters;
    // Per period and, where the period divides 1 ms, in 1 ms differences too.
    const test::MeasuredCase mc = test::measure_case(p, c.blocks, t);
    const Measured& m = mc.per_period;
    ASSERT_TRUE(m.finite);
    ASSERT_EQ(m.end_position, c.blocks.back().target);  // exact
    ASSERT_EQ(t.samples.back().velocity, AxisVector::Zero());
    ASSERT_EQ(m.corner_errors.size(), mc.points.size() < 2 ? 0u : mc.points.size() - 2);
    for (std::size_t i = 0; i < m.corner_errors.size(); ++i) {
        if (!mc.blended_turn(i)) continue;
        const Block& b = *mc.ending[i];
        ASSERT_LE(m.corner_errors[i], b.tolerance) << "corner after line " << b.line;
        worst.corner = std::max(worst.corner, m.corner_errors[i] / b.tolerance);
        ++worst.corners;
    }
    for (int a = 0; a < p.limits.axes; ++a) {
        const AxisLimits& l = p.limits.axis[a];
        const double slack = 1.0 + 1e-6;
        for (const AxisState& s : t.samples) {
            ASSERT_LE(std::abs(s.velocity[a]), l.max_velocity * slack) << "axis " << a << " at " << s.time;
            ASSERT_LE(std::abs(s.acceleration[a]), l.max_acceleration * slack) << "axis " << a << " at " << s.time;
            if (l.max_jerk > 0.0) {
                ASSERT_LE(std::abs(s.jerk[a]), l.max_jerk * slack) << "axis " << a << " at " << s.time;
            }
        }
        for (const Measured* d : {&m, &mc.per_ms}) {
            const double period = d == &m ? mc.period : mc.ms_period;
            ASSERT_LE(d->max_velocity[a], l.max_velocity * slack) << "axis " << a << (d == &m ? " per period" : " per ms");
            ASSERT_LE(d->max_acceleration[a], l.max_acceleration * slack + test::difference_noise(t.samples, a, period, 2))
                << "axis " << a;
            if (l.max_jerk > 0.0) {
                ASSERT_LE(d->max_jerk[a], l.max_jerk * slack + test::difference_noise(t.samples, a, period, 3)) << "axis " << a;
            }
        }
        worst.velocity = std::max(worst.velocity, m.max_velocity[a] / l.max_velocity);
        worst.acceleration = std::max(worst.acceleration, m.max_acceleration[a] / l.max_acceleration);
        if (l.max_jerk > 0.0) worst.jerk = std::max(worst.jerk, m.max_jerk[a] / l.max_jerk);
    }
}

void check_programs(std::uint64_t seed, int count, ToleranceMeaning meaning) {
    seed += test::random_seed_offset();
    std::mt19937_64 rng(seed);
    Worst worst;
    for (int k = 0; k < test::random_scaled(count); ++k) {
        test::RandomCase c = test::random_case(rng);
        c.parameters.tolerance_meaning = meaning;
        if (meaning == ToleranceMeaning::contour)  // one tolerance: the measured largest is against it
            for (Block& b : c.blocks) b.tolerance = c.blocks.front().tolerance;
        SCOPED_TRACE("seed " + std::to_string(seed) + " program " + std::to_string(k));
        Trajectory t;
        try {
            t = plan_trajectory(c.parameters, AxisVector::Zero(), c.blocks);
        } catch (const std::invalid_argument& refused) {
            FAIL() << refused.what();
        }
        EXPECT_EQ(t.stats.refused, 0u);
        EXPECT_EQ(t.stats.unfit, 0u);
        if (meaning == ToleranceMeaning::corner_point) {
            expect_within(c, t, worst);
        } else {
            std::vector<AxisVector> points{AxisVector::Zero()};
            for (const Block& b : c.blocks) points.push_back(b.target);
            const Measured m = measure(t.samples, points, c.parameters.period);
            ASSERT_EQ(m.end_position, c.blocks.back().target);
            ASSERT_LE(m.max_contour_error, c.blocks.front().tolerance * (1 + 1e-6) + 1e-9);
        }
        ASSERT_FALSE(::testing::Test::HasFailure());
        ++worst.programs;
        worst.blocks += c.blocks.size();
    }
    std::printf("%zu programs, %zu blocks, %zu corners: worst corner error / tolerance %.4f, |v| %.4f, |a| %.4f, "
                "|j| %.4f of the limits (finite differences)\n",
                worst.programs, worst.blocks, worst.corners, worst.corner, worst.velocity, worst.acceleration, worst.jerk);
}

}  // namespace

TEST(RandomMachines, CornersLimitsAndEndHoldOnEverySample) { check_programs(21, 300, ToleranceMeaning::corner_point); }

TEST(RandomMachines, ContourToleranceHolds) { check_programs(22, 100, ToleranceMeaning::contour); }

// The same programs on machines with one to three more axes that do not move, their jerk stages
// mostly far longer (1e3-1e6 mm/s^3): each step's stage is that of the axes moving in it
// (lookahead.hpp, Regime), the others held within it, so every axis keeps its limits, and the
// programs take about as long as without those axes.
TEST(RandomMachines, AxesThatDoNotMoveKeepTheirLimitsAndLeaveTheStagesAlone) {
    const std::uint64_t seed = 23 + test::random_seed_offset();
    std::mt19937_64 rng(seed);
    Worst worst;
    std::size_t widened = 0, slower = 0;
    double own_time = 0.0, more_time = 0.0, slowest = 1.0;
    for (int k = 0; k < test::random_scaled(200); ++k) {
        test::RandomCase c = test::random_case(rng);
        const double own = static_cast<double>(plan_trajectory(c.parameters, AxisVector::Zero(), c.blocks).samples.size()) * c.parameters.period;
        MachineLimits& l = c.parameters.limits;
        const int axes = std::min(9, l.axes + 1 + static_cast<int>(rng() % 3));
        for (int a = l.axes; a < axes; ++a) {
            l.axis[a].max_velocity = test::log_uniform(rng, 20, 300);
            l.axis[a].max_acceleration = test::log_uniform(rng, 100, 3000);
            l.axis[a].max_jerk = test::log_uniform(rng, 1e3, 1e6);
        }
        const double before = jerk_time(smoothing_limits(l));
        l.axes = axes;
        if (jerk_time(smoothing_limits(l)) > before) ++widened;
        SCOPED_TRACE("seed " + std::to_string(seed) + " program " + std::to_string(k));
        const Trajectory t = plan_trajectory(c.parameters, AxisVector::Zero(), c.blocks);
        EXPECT_EQ(t.stats.refused, 0u);
        EXPECT_EQ(t.stats.unfit, 0u);
        expect_within(c, t, worst);
        ASSERT_FALSE(::testing::Test::HasFailure());
        ++worst.programs;
        worst.blocks += c.blocks.size();
        const double more = static_cast<double>(t.samples.size()) * c.parameters.period;
        own_time += own, more_time += more;
        if (more > own * (1 + 1e-9)) ++slower, slowest = std::max(slowest, more / own);
    }
    std::printf("%zu programs (%zu with the machine's T2 widened by an axis that does not move), %zu corners: worst corner "
                "error / tolerance %.4f, |v| %.4f, |a| %.4f, |j| %.4f of the limits (finite differences); cycle times "
                "%.3f s against %.3f s without those axes, %zu slower (at most %.3fx)\n",
                worst.programs, widened, worst.corners, worst.corner, worst.velocity, worst.acceleration, worst.jerk, more_time,
                own_time, slower, slowest);
    EXPECT_GT(widened, worst.programs / 2);
    // (With every step's stage every axis': 380.392 s against 361.421 s, 115 slower, up to 8.5x.)
    EXPECT_LT(more_time, own_time * 1.01);
    EXPECT_LT(slowest, 1.5);
}

// The check sums the legs of a context of blocks before the re-planned ones, and sweeps the limits
// from the widest kernel back. Where the newest legs brought a kernel wider than any before, the
// sweep reached past the context: a step at its edge rose without the leg it ends, a jump of that
// leg's whole speed over a stage of 0.14 ms (1.2e9 mm/s^3 in program 422 of firtp_cliffs' seed 31),
// and the plan was refused, its corner lowered for nothing. These programs were refused so (1 to
// 3 times, each): none now, and within the limits and tolerances.
TEST(RandomMachines, NoRefusalFromASweepBeyondItsContext) {
    for (const auto& [seed, program] : {std::pair{21, 199}, std::pair{7, 273}, std::pair{5, 716}}) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
        test::RandomCase c = test::random_case(rng);
        for (int k = 0; k < program; ++k) c = test::random_case(rng);
        SCOPED_TRACE("seed " + std::to_string(seed) + " program " + std::to_string(program));
        const Trajectory t = plan_trajectory(c.parameters, AxisVector::Zero(), c.blocks);
        EXPECT_EQ(t.stats.checks_failed, 0u);
        Worst worst;
        expect_within(c, t, worst);
        EXPECT_GT(worst.corners, 0u);
    }
}
