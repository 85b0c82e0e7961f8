// Fig. 4 (one stage, 90 deg corner) and the diamond of Section 4, measured on the sampled output.
#include "support/reference.hpp"

#include <firtp/measure.hpp>
#include <firtp/overlap.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace firtp;
using firtp::test::chain_of;
using firtp::test::line_to;
using firtp::test::xyz;

namespace {


std::vector<AxisVector> points_of(const AxisVector& start, const std::vector<Block>& blocks) {
    std::vector<AxisVector> points{start};
    for (const Block& b : blocks) points.push_back(b.target);
    return points;
}

struct Figure4 : ::testing::Test {
    PlannerParameters parameters;
    std::vector<Block> blocks;
    AxisVector corner, end;
    void SetUp() override {
        parameters.fixed_chain = true;
        parameters.filters = chain_of({0.020});
        parameters.period = 0.001;
        // The paper's orientation: X keeps F cos 45 while Y reverses from +F sin 45 to -F sin 45.
        const double leg = 2.5 * std::sqrt(0.5);
        corner = xyz(leg, leg);
        end = xyz(2 * leg, 0);
        blocks = {line_to(corner, 50, 1.0, 1), line_to(end, 50, 1.0, 2)};
    }
    Measured run() {
        const Trajectory t = plan_trajectory(parameters, AxisVector::Zero(), blocks);
        return measure(t.samples, points_of(AxisVector::Zero(), blocks), parameters.period);
    }
};

}  // namespace

TEST_F(Figure4, ExactStopTakesSeventyMillisecondsPerBlock) {
    blocks[0].termination = Termination::exact_stop;
    const Trajectory t = plan_trajectory(parameters, AxisVector::Zero(), blocks);
    ASSERT_EQ(t.samples.size(), 141u);  // 0 .. 140 ms
    EXPECT_NEAR(t.cycle_time, 0.140, 1e-12);
    const AxisState& at_corner = t.samples[70];
    EXPECT_NEAR((at_corner.position - corner).norm(), 0.0, 1e-12);
    EXPECT_NEAR(at_corner.velocity.norm(), 0.0, 1e-9);
    EXPECT_GT((t.samples[69].position - corner).norm(), 1e-6);  // still arriving at 69 ms
    EXPECT_EQ(t.samples.back().position, end);
}

TEST_F(Figure4, FullOverlapReversesYAt3535AndCutsTheCornerBy0_1768) {
    parameters.fixed_overlap = 0.020;
    const Trajectory t = plan_trajectory(parameters, AxisVector::Zero(), blocks);
    const Measured m = measure(t.samples, points_of(AxisVector::Zero(), blocks), parameters.period);
    EXPECT_NEAR(m.max_acceleration[1], 3535.5, 0.1);  // 2 F sin 45 / T1, finite differences
    double peak_y = 0;
    for (const AxisState& s : t.samples) peak_y = std::max(peak_y, std::abs(s.acceleration[1]));
    EXPECT_NEAR(peak_y, 2 * 50 * std::sin(M_PI / 4) / 0.020, 1e-6);
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_NEAR(m.corner_errors[0], 0.1768, 5e-5);
    EXPECT_NEAR(t.cycle_time, 0.120, 1e-12);  // no gap: 50 + 50 + 20 ms
    EXPECT_NEAR(m.max_velocity[0], 50 * std::sqrt(0.5), 1e-9);  // X does not slow down
    double slowest_x = 1e300;
    for (std::size_t i = 20; i <= 100; ++i) slowest_x = std::min(slowest_x, t.samples[i].velocity[0]);
    EXPECT_NEAR(slowest_x, 50 * std::sqrt(0.5), 1e-9);
    EXPECT_EQ(m.end_position, end);
}

TEST_F(Figure4, HalfOverlapCutsTheCornerBy0_0442) {
    parameters.fixed_overlap = 0.010;
    const Measured m = run();
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_NEAR(m.corner_errors[0], 0.0442, 5e-5);
    EXPECT_NEAR(m.cycle_time, 0.130, 1e-12);
}

TEST_F(Figure4, ToleranceGivesTheOverlapOfEq13AndIsKept) {
    blocks[0].tolerance = 0.0442;
    const Trajectory t = plan_trajectory(parameters, AxisVector::Zero(), blocks);
    const Measured m = measure(t.samples, points_of(AxisVector::Zero(), blocks), parameters.period);
    ASSERT_EQ(t.corners.size(), 1u);
    EXPECT_NEAR(t.corners[0].Tk_tolerance, overlap_eq13(0.0442, 50, M_PI / 2, 0.020), 2e-4);
    EXPECT_LE(m.corner_errors[0], 0.0442);
    EXPECT_GT(m.corner_errors[0], 0.0442 * 0.97);
}

TEST(Diamond, EveryCornerWithinHalfAMillimetreAndCycleTimeOfTheClosedForm) {
    PlannerParameters parameters;
    parameters.fixed_chain = true;
    parameters.filters = chain_of({0.148, 0.089});
    parameters.period = 0.001;
    const std::vector<Block> blocks{line_to(xyz(25, 25), 250, 0.5, 4), line_to(xyz(50, 0), 250, 0.5, 5),
                                    line_to(xyz(25, -25), 250, 0.5, 6), line_to(xyz(0, 0), 250, 0.5, 7)};
    const Trajectory t = plan_trajectory(parameters, AxisVector::Zero(), blocks);
    const Measured m = measure(t.samples, points_of(AxisVector::Zero(), blocks), parameters.period);

    ASSERT_EQ(m.corner_errors.size(), 3u);
    for (double e : m.corner_errors) {
        EXPECT_LE(e, 0.5);
        EXPECT_GT(e, 0.49);  // the tolerance is used, not wasted
    }
    const double tv = std::hypot(25.0, 25.0) / 250, td = 0.148 + 0.089;
    const double Tk = overlap_eq14(0.5, 250, M_PI / 2, 0.148, 0.089);
    const double closed_form = 4 * tv + 3 * (td - Tk) + td;
    EXPECT_NEAR(closed_form, 1.2247, 1e-4);
    EXPECT_NEAR(m.cycle_time, closed_form, 0.01 * closed_form);
    EXPECT_EQ(m.end_position, AxisVector::Zero());
    EXPECT_LT(m.max_path_speed, 250.0);
    EXPECT_NEAR(m.max_path_speed, 207, 3);  // blocks shorter than T1: the speed never reaches F
    for (const CornerReport& c : t.corners) EXPECT_NEAR(c.Tk, 0.09634, 0.001);
}
