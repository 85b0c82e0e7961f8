// junction.hpp: the corner speeds in closed form, held to the error they bound.
#include <firtp/junction.hpp>
#include <firtp/kernel.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace firtp;

namespace {

// The corner error of a turn s at speed v, with the chord margin of the step's peak (junction.hpp).
double sampled_error(double alpha, double t2, double s, double du, double jerk, double period, double v) {
    const double t1 = v * alpha;
    const double peak = t1 > 0.0 ? v * du / std::max(t1, t2) : 0.0;
    return 2.0 * s * v * two_stage(t1, t2).lead() + chord_margin(peak, jerk, period);
}

}  // namespace

// The highest speed within epsilon: at it the error is at most epsilon, 1e-9 faster it is more.
// Random turns, machines and tolerances, on both sides of T1 = T2 and of the margin's kink.
TEST(CornerSpeed, SampledIsTheHighestSpeedWithinTheTolerance) {
    std::mt19937_64 rng(13);
    auto log_uniform = [&](double lo, double hi) {
        return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
    };
    int below_box = 0, above_box = 0;
    for (int n = 0; n < 200000; ++n) {
        const double alpha = log_uniform(1e-5, 1.0);       // s per mm/s: T1 per unit of speed
        const double t2 = n % 7 == 0 ? 0.0 : log_uniform(1e-4, 0.2);
        const double s = log_uniform(1e-4, 1.0);
        const double du = 2.0 * s * log_uniform(0.3, 1.0);  // |u_out - u_in| = 2 s, axes' share of it
        const double jerk = log_uniform(1e2, 1e9);
        const double period = n % 3 == 0 ? 0.001 : log_uniform(1e-4, 4e-3);
        const double epsilon = log_uniform(1e-5, 5.0);
        const double v = sampled_corner_speed(alpha, t2, s, du, jerk, period, epsilon);
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0) << n;
        ASSERT_LE(v, corner_speed(alpha, t2, s, epsilon)) << n;
        ASSERT_LE(sampled_error(alpha, t2, s, du, jerk, period, v), epsilon) << n;
        const double faster = v * (1.0 + 1e-9) + 1e-300;
        ASSERT_GT(sampled_error(alpha, t2, s, du, jerk, period, faster), epsilon) << n << " v " << v;
        (v * alpha < t2 ? below_box : above_box) += 1;
    }
    EXPECT_GT(below_box, 20000);
    EXPECT_GT(above_box, 20000);
}

// Without the chords the corner error is 2 s V lead(V alpha, t2) = epsilon exactly.
TEST(CornerSpeed, ClosedFormMeetsTheTolerance) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 100000; ++n) {
        const double alpha = 1e-4 + 0.1 * unit(rng), t2 = n % 5 == 0 ? 0.0 : 0.1 * unit(rng);
        const double s = 0.01 + 0.99 * unit(rng), epsilon = 1e-4 + unit(rng);
        const double v = corner_speed(alpha, t2, s, epsilon);
        ASSERT_NEAR(2.0 * s * v * two_stage(v * alpha, t2).lead(), epsilon, 1e-9 * epsilon) << n;
    }
}
