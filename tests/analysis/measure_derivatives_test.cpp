// Finite-difference velocity, acceleration and jerk of polynomial motions.
#include "trajectories.hpp"

#include <firtp/measure.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace firtp {
namespace {

// x(t) = c2 t^2 / 2 + c3 t^3 / 6 on one axis, sampled at 0, period, ..., (n-1) period.
void add_polynomial(std::vector<AxisState>& samples, int axis, double c2, double c3) {
    for (AxisState& s : samples) s.position(axis) += c2 * s.time * s.time / 2.0 + c3 * s.time * s.time * s.time / 6.0;
}

std::vector<AxisState> at_rest(std::size_t n, double period) {
    return test::timed(std::vector<AxisVector>(n, AxisVector::Zero()), period);
}

TEST(MeasureDerivatives, ConstantAcceleration) {
    const double period = 1e-3;
    auto samples = at_rest(1001, period);
    add_polynomial(samples, 0, 2.0, 0.0);   // X
    add_polynomial(samples, 4, -3.0, 0.0);  // B
    const double t_end = 1.0;
    const Measured m = measure(samples, {}, period);

    EXPECT_DOUBLE_EQ(m.cycle_time, t_end);
    EXPECT_NEAR(m.end_position(0), 1.0, 1e-12);
    EXPECT_NEAR(m.end_position(4), -1.5, 1e-12);
    EXPECT_NEAR(m.max_acceleration(0), 2.0, 1e-6);
    EXPECT_NEAR(m.max_acceleration(4), 3.0, 1e-6);
    EXPECT_LT(m.max_jerk(0), 1e-3);
    EXPECT_LT(m.max_jerk(4), 1e-3);
    // Last first difference is the velocity half a period before the end.
    EXPECT_NEAR(m.max_velocity(0), 2.0 * t_end, 2.0 * period);
    EXPECT_NEAR(m.max_velocity(0), 2.0 * (t_end - period / 2.0), 1e-9);
    EXPECT_NEAR(m.max_velocity(4), 3.0 * (t_end - period / 2.0), 1e-9);
    EXPECT_NEAR(m.max_path_speed, std::sqrt(13.0) * (t_end - period / 2.0), 1e-9);
    for (int axis : {1, 2, 3, 5, 6, 7, 8}) {
        EXPECT_EQ(m.max_velocity(axis), 0.0);
        EXPECT_EQ(m.max_acceleration(axis), 0.0);
        EXPECT_EQ(m.max_jerk(axis), 0.0);
    }
    EXPECT_TRUE(m.finite);
}

TEST(MeasureDerivatives, ConstantJerk) {
    const double period = 1e-2;
    auto samples = at_rest(101, period);
    add_polynomial(samples, 2, 0.0, 6.0);   // Z
    add_polynomial(samples, 8, 0.0, -2.0);  // W
    const Measured m = measure(samples, {}, period);

    EXPECT_NEAR(m.max_jerk(2), 6.0, 1e-6);
    EXPECT_NEAR(m.max_jerk(8), 2.0, 1e-6);
    // Second difference at t is jerk * t * period^2: largest at the last interior sample.
    EXPECT_NEAR(m.max_acceleration(2), 6.0 * 0.99, 1e-9);
    EXPECT_NEAR(m.max_acceleration(8), 2.0 * 0.99, 1e-9);
    EXPECT_NEAR(m.max_velocity(2), (1.0 - std::pow(0.99, 3)) / period, 1e-9);
    EXPECT_NEAR(m.max_velocity(8), (1.0 - std::pow(0.99, 3)) / 3.0 / period, 1e-9);
}

TEST(MeasureDerivatives, ScaleWithPeriod) {
    // Same positions, twice the period: derivatives drop by 2, 4 and 8.
    auto samples = at_rest(50, 1e-3);
    add_polynomial(samples, 0, 4.0, 9.0);
    const Measured fast = measure(samples, {}, 1e-3);
    const Measured slow = measure(samples, {}, 2e-3);
    EXPECT_NEAR(slow.max_velocity(0), fast.max_velocity(0) / 2.0, 1e-9);
    EXPECT_NEAR(slow.max_acceleration(0), fast.max_acceleration(0) / 4.0, 1e-9);
    EXPECT_NEAR(slow.max_jerk(0), fast.max_jerk(0) / 8.0, 1e-6);
    EXPECT_GT(fast.max_jerk(0), 8.0);
}

}  // namespace
}  // namespace firtp
