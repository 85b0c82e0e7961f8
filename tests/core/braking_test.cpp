// A stop from the velocity the axes have at a start (Planner::brake_from): no jump in position or
// velocity, a smooth deceleration, rest exactly where braking_rest() says, within the limits.
// The paper's chain brakes as a pulse's falling edge and can stop only a share of a fast
// velocity (braking_share); smoothing at the limits sizes the stop to the velocity, so any
// velocity within the axes' speed limits stops within their acceleration and jerk limits.
#include "support/limits.hpp"
#include "support/reference.hpp"

#include <firtp/braking.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <random>

using namespace firtp;

namespace {

struct Stop {
    AxisState first;
    std::vector<AxisState> samples;
    AxisVector rest;
};

// Runs `idle_ticks` first (at rate `rate` for the paper's clock), then brakes.
Stop brake(const PlannerParameters& parameters, const AxisVector& p, const AxisVector& v, int idle_ticks, double rate) {
    Planner planner(parameters, AxisVector::Zero());
    AxisState s;
    planner.set_rate(rate);
    for (int k = 0; k < idle_ticks; ++k) planner.tick(s);
    planner.brake_from(p, v);
    Stop stop;
    stop.rest = planner.braking_rest(p, v);
    planner.tick(stop.first);
    stop.samples.push_back(stop.first);
    while (!planner.idle()) {
        planner.tick(s);
        stop.samples.push_back(s);
    }
    planner.tick(s);
    stop.samples.push_back(s);
    return stop;
}

PlannerParameters fixed_chain(const FilterTimes& times) {
    PlannerParameters p;
    p.fixed_chain = true;
    p.filters = times;
    return p;
}

}  // namespace

TEST(Braking, PeaksAreTheChainsClosedForm) {
    const BrakingPeaks two = braking_peaks(FirChain(test::chain_of({0.148, 0.089})));
    EXPECT_NEAR(two.acceleration, 1.0 / 0.148, 1e-5 / 0.148);  // trapezoid of height 1/T1
    EXPECT_NEAR(two.jerk, 1.0 / (0.148 * 0.089), 1e-5 / (0.148 * 0.089));
    const BrakingPeaks one = braking_peaks(FirChain(test::chain_of({0.02})));
    EXPECT_NEAR(one.acceleration, 1.0 / 0.02, 1e-5 / 0.02);
}

TEST(Braking, ContinuesThroughThePositionAtTheVelocityAndRestsExactly) {
    for (const FilterTimes& times : {test::chain_of({0.148, 0.089}), test::chain_of({0.0371, 0.0133, 0.0049}),
                                     test::chain_of({0.02}), test::chain_of({0.03, 0.02, 0.01, 0.005})}) {
        const PlannerParameters parameters = fixed_chain(times);
        const FirChain chain(times);
        const BrakingPeaks peaks = braking_peaks(chain);
        const AxisVector p = test::xyz(12.5, -3.25, 7.0), v = test::xyz(80.0, -45.0, 10.0);
        for (const double rate : {1.0, 0.37}) {  // 0.37: an override in effect before the stop
            const Stop stop = brake(parameters, p, v, 57, rate);
            EXPECT_LT((stop.first.position - p).cwiseAbs().maxCoeff(), 1e-12);
            EXPECT_LT((stop.first.velocity - v).cwiseAbs().maxCoeff(), 1e-9);
            EXPECT_LT(stop.first.acceleration.cwiseAbs().maxCoeff(), 1e-6);
            EXPECT_EQ(stop.samples.back().position, stop.rest);  // exactly
            EXPECT_EQ(stop.samples.back().velocity, AxisVector::Zero());
            // Decelerates monotonically along v, never beyond the chain's peaks.
            double worst_a = 0.0;
            for (std::size_t k = 1; k < stop.samples.size(); ++k) {
                const AxisState& s = stop.samples[k];
                ASSERT_LE(s.velocity[0], stop.samples[k - 1].velocity[0] + 1e-9);
                ASSERT_GE(s.velocity[0], -1e-9);
                worst_a = std::max(worst_a, std::abs(s.acceleration[0]) / (80.0 * peaks.acceleration));
            }
            EXPECT_LE(worst_a, 1.0);
            EXPECT_GT(worst_a, 0.98);  // the peaks are tight, not loose bounds
            EXPECT_NEAR(static_cast<double>(stop.samples.size()) * 0.001, chain.delay(), 0.0035);  // + the first and the retiring tick
        }
    }
}

// Random velocities up to 3 times the limits: the share stops them within every limit.
TEST(Braking, ShareKeepsTheStopWithinTheAxisLimits) {
    const MachineLimits limits = test::uniform_limits(250.0, 2000.0, 40000.0);
    const FilterTimes times = test::chain_of({0.148, 0.089});  // slow enough that some stops fit whole
    const BrakingPeaks peaks = braking_peaks(FirChain(times));
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> component(-750.0, 750.0);
    int whole = 0, scaled = 0;
    double worst = 0.0;
    for (int trial = 0; trial < 300; ++trial) {
        AxisVector v = AxisVector::Zero();
        for (int a = 0; a < 3; ++a) v[a] = component(rng) * (trial % 3 == 0 ? 0.02 : 1.0);
        const double share = braking_share(peaks, limits, v);
        ASSERT_GT(share, 0.0);
        ASSERT_LE(share, 1.0);
        (share == 1.0 ? whole : scaled) += 1;
        const Stop stop = brake(fixed_chain(times), test::xyz(1, 2, 3), share * v, trial % 7, 1.0);
        const double ratio = test::worst_ratio(stop.samples, limits);
        ASSERT_LE(ratio, 1.0 + 1e-9) << "trial " << trial;
        worst = std::max(worst, ratio);
    }
    EXPECT_GT(whole, 50);
    EXPECT_GT(scaled, 50);
    EXPECT_GT(worst, 0.99);  // a scaled stop reaches a limit
}

// At the limits: any velocity within the speed limits stops whole, its most loaded axis at its
// acceleration limit, every axis within acceleration and jerk, at rest exactly where promised.
TEST(Braking, AtTheLimitsAnyVelocityStopsWholeWithinTheLimits) {
    PlannerParameters parameters;
    parameters.limits = test::uniform_limits(250.0, 2000.0, 40000.0);
    parameters.limits.axis[2] = {80.0, 700.0, 9000.0};
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    double worst = 0.0;
    for (int trial = 0; trial < 300; ++trial) {
        AxisVector v = AxisVector::Zero();
        for (int a = 0; a < 3; ++a) v[a] = parameters.limits.axis[a].max_velocity * unit(rng) * (trial % 3 == 0 ? 0.02 : 1.0);
        const AxisVector p = test::xyz(1, 2, 3);
        const Stop stop = brake(parameters, p, v, trial % 7, 1.0);
        EXPECT_LT((stop.first.position - p).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LT((stop.first.velocity - v).cwiseAbs().maxCoeff(), 1e-9);
        ASSERT_EQ(stop.samples.back().position, stop.rest);
        ASSERT_EQ(stop.samples.back().velocity, AxisVector::Zero());
        const double ratio = test::worst_ratio(stop.samples, parameters.limits);
        ASSERT_LE(ratio, 1.0 + 1e-9) << "trial " << trial;
        worst = std::max(worst, ratio);
    }
    EXPECT_GT(worst, 0.99);  // stops at the limits, not far inside them
}
