// The mode simulation against closed-form responses, the reference S-curve planner against its
// limits and closed-form duration, and the acceleration spectrum against a known sum.
#include <firtp/mode_response.hpp>
#include <firtp/mode_tuning.hpp>
#include <firtp/trajectory.hpp>
#include <firtp/reference_planner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace firtp {
namespace {

constexpr double pi = std::numbers::pi;

// Axis 0 with a(t) = a0 + j t from t = 0, sampled every `period`.
std::vector<AxisState> ramp(double a0, double j, double period, int count) {
    std::vector<AxisState> out(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        AxisState& s = out[static_cast<std::size_t>(k)];
        s.time = k * period;
        s.acceleration[0] = a0 + j * s.time;
        s.jerk[0] = j;
        s.velocity[0] = 1.0;  // moving
    }
    return out;
}

TEST(ModeResponse, StepAccelerationMatchesClosedForm) {
    const double f = 6.8, zeta = 0.02, a0 = 1200.0, period = 0.001;
    const double w = 2 * pi * f, sigma = zeta * w, wd = w * std::sqrt(1 - zeta * zeta);
    const std::vector<AxisState> samples = ramp(a0, 0.0, period, 2000);
    const ModeResponse r = simulate_mode(samples, 0, f, zeta, period);
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const double t = samples[k].time;
        const double x = -a0 / (w * w) * (1 - std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t)));
        ASSERT_NEAR(r.deflection[k], x, 1e-12 * a0 / (w * w)) << t;
        // The oscillation about the static lag -a0 / w^2 decays from a0 / w^2 (times wd / w).
        const double envelope = a0 / (w * w) * std::exp(-sigma * t) * w / wd;
        ASSERT_NEAR(r.vibration[k], envelope, 1e-10 * envelope) << t;
    }
}

// Constant jerk: the oscillation about the forced response is free, so its amplitude only decays.
TEST(ModeResponse, RampEnvelopeOnlyDecays) {
    const double f = 11.4, zeta = 0.03, jerk = 50000.0, period = 0.001;
    const double w = 2 * pi * f, sigma = zeta * w;
    const std::vector<AxisState> samples = ramp(0.0, jerk, period, 1000);
    const ModeResponse r = simulate_mode(samples, 0, f, zeta, period);
    for (std::size_t k = 0; k < samples.size(); ++k)
        ASSERT_NEAR(r.vibration[k], r.vibration[0] * std::exp(-sigma * samples[k].time), 1e-10 * r.vibration[0]);
}

TEST(ReferencePlanner, SCurveKeepsLimitsAndClosedFormDuration) {
    const double v = 200.0, a = 4000.0, j = 80000.0;
    const SCurve longest(100.0, v, a, j);
    EXPECT_NEAR(longest.duration(), 100.0 / v + v / a + a / j, 1e-12);
    EXPECT_NEAR(longest.peak_velocity(), v, 1e-12);
    double vmax = 0.0, amax = 0.0, jmax = 0.0;
    for (double t = 0.0; t <= longest.duration(); t += 1e-4) {
        const SCurve::State s = longest.at(t);
        vmax = std::max(vmax, std::abs(s.v));
        amax = std::max(amax, std::abs(s.a));
        jmax = std::max(jmax, std::abs(s.j));
    }
    EXPECT_LE(vmax, v * (1 + 1e-12));
    EXPECT_LE(amax, a * (1 + 1e-12));
    EXPECT_LE(jmax, j * (1 + 1e-12));
    EXPECT_NEAR(longest.at(longest.duration()).s, 100.0, 1e-12);

    // Too short to reach v or a: bisected peak speed, still ends on the length at rest.
    const SCurve short_move(0.5, v, a, j);
    EXPECT_LT(short_move.peak_velocity(), v);
    const SCurve::State end = short_move.at(short_move.duration() * (1 - 1e-12));
    EXPECT_NEAR(end.s, 0.5, 1e-9);
    EXPECT_NEAR(end.v, 0.0, 1e-6);
    // No jerk limit: a trapezoid in velocity, T = L / v + v / a.
    EXPECT_NEAR(SCurve(100.0, v, a, 0.0).duration(), 100.0 / v + v / a, 1e-12);
}

TEST(ReferencePlanner, ExactStopAtEveryBlockAndModeResidualAtStops) {
    MachineLimits limits;
    limits.axes = 2;
    limits.axis[0] = limits.axis[1] = AxisLimits{300.0, 4000.0, 80000.0};
    std::vector<Block> blocks(2);
    blocks[0].target << 25, 25, 0, 0, 0, 0, 0, 0, 0;
    blocks[1].target << 50, 0, 0, 0, 0, 0, 0, 0, 0;
    blocks[0].feed = blocks[1].feed = 250.0;
    blocks[0].line = 1;
    blocks[1].line = 2;
    const std::vector<AxisState> samples = plan_exact_stop_scurves(limits, 0.001, AxisVector::Zero(), blocks);
    EXPECT_EQ(samples.back().position, blocks[1].target);
    double ax = 0.0, jx = 0.0;
    for (const AxisState& s : samples) {
        ax = std::max(ax, std::abs(s.acceleration[0]));
        jx = std::max(jx, std::abs(s.jerk[0]));
    }
    EXPECT_LE(ax, 4000.0 * (1 + 1e-12));
    EXPECT_LE(jx, 80000.0 * (1 + 1e-12));
    const ModeResponse r = simulate_mode(samples, 0, 11.4, 0.03, 0.001);
    ASSERT_EQ(r.stops.size(), 2u);  // between the blocks and at the end
    EXPECT_EQ(r.stops.back().sample, samples.size() - 1);
    EXPECT_GT(r.max_stop_residual, 0.0);
    EXPECT_EQ(r.final_residual, r.stops.back().amplitude);
    EXPECT_GT(r.max_moving_deflection, 0.0);
}

// One block, one stop: the residual after the firtp chain is the unfiltered one times the chain's
// V (mode_tuning.hpp), so tuned over untuned is V(tuned) / V(untuned) = 0.0158, matched within
// 0.02 % (the cubic hold across the chain's knots between samples is all that differs).
TEST(ModeResponse, FirtpStopResidualFollowsTheChainsResidualVibration) {
    const double period = 0.001, f = 6.8, zeta = 0.02;
    const double sigma = zeta * 2 * pi * f;
    std::vector<Block> block(1);
    block[0].target << 100, 0, 0, 0, 0, 0, 0, 0, 0;
    block[0].feed = 200.0;
    block[0].termination = Termination::exact_stop;
    const auto residual = [&](double t1, double t2) {
        PlannerParameters p;
        p.fixed_chain = true;
        p.filters.stages = 2;
        p.filters.T = {t1, t2, 0.0, 0.0};
        p.period = period;
        const Trajectory trajectory = plan_trajectory(p, AxisVector::Zero(), block);
        const ModeResponse r = simulate_mode(trajectory.samples, 0, f, zeta, period);
        // Back to the exact end of the motion, Tv + Td, from the first sample at rest after it.
        const double stop = 100.0 / 200.0 + t1 + t2;
        return r.final_residual * std::exp(sigma * (trajectory.samples.back().time - stop));
    };
    FilterTimes tuned, untuned;
    tuned.T = {1.0 / 6.8, 1.0 / 11.4, 0.0, 0.0};
    untuned.T = {0.06, 0.05, 0.0, 0.0};
    const double expected = residual_vibration(tuned, f, zeta) / residual_vibration(untuned, f, zeta);
    EXPECT_NEAR(residual(1.0 / 6.8, 1.0 / 11.4) / residual(0.06, 0.05), expected, 2e-4 * expected);
}

TEST(ModeResponse, SpectrumOfAConstantBurst) {
    const double period = 0.001, a = 100.0, f = 7.0;
    const int n = 300;
    std::vector<AxisState> samples = ramp(a, 0.0, period, n);
    const std::vector<double> freqs{f};
    const double expected = a * std::abs(std::sin(pi * f * n * period) / std::sin(pi * f * period)) * period;
    EXPECT_NEAR(acceleration_spectrum(samples, 0, freqs)[0], expected, 1e-9 * expected);
}

}  // namespace
}  // namespace firtp
