// A stop from the velocity the axes have at a start (Interpolator::brake_from): no jump in
// position or velocity, the chain's smooth deceleration, rest exactly where braking_rest() says,
// and braking_share() keeps it within the axis limits.
#include "support/limits.hpp"
#include "support/reference.hpp"

#include <firtp/braking.hpp>
#include <firtp/interpolator.hpp>

#include <gtest/gtest.h>

#include <random>

using namespace firtp;

namespace {

struct Stop {
    AxisState first;
    std::vector<AxisState> samples;
};

// Runs `idle_ticks` at rate `rate` first so the clock has a fraction, then brakes.
Stop brake(const FirChain& chain, const AxisVector& p, const AxisVector& v, int idle_ticks, double rate) {
    Interpolator interpolator(chain, 0.001, 8, AxisVector::Zero());
    AxisState s;
    interpolator.set_rate(rate);
    for (int k = 0; k < idle_ticks; ++k) interpolator.tick(s);
    interpolator.brake_from(p, v);
    Stop stop;
    interpolator.tick(stop.first);
    stop.samples.push_back(stop.first);
    while (!interpolator.idle()) {
        interpolator.tick(s);
        stop.samples.push_back(s);
    }
    interpolator.tick(s);
    stop.samples.push_back(s);
    return stop;
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
        const FirChain chain(times);
        const BrakingPeaks peaks = braking_peaks(chain);
        const AxisVector p = test::xyz(12.5, -3.25, 7.0), v = test::xyz(80.0, -45.0, 10.0);
        for (const double rate : {1.0, 0.37}) {  // 0.37: an override in effect before the stop
            const Stop stop = brake(chain, p, v, 57, rate);
            EXPECT_LT((stop.first.position - p).cwiseAbs().maxCoeff(), 1e-12);
            EXPECT_LT((stop.first.velocity - v).cwiseAbs().maxCoeff(), 1e-9);
            EXPECT_LT(stop.first.acceleration.cwiseAbs().maxCoeff(), 1e-6);
            EXPECT_EQ(stop.samples.back().position, braking_rest(chain, p, v));  // exactly
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
    const FirChain chain(test::chain_of({0.148, 0.089}));  // slow enough that some stops fit whole
    const BrakingPeaks peaks = braking_peaks(chain);
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
        const Stop stop = brake(chain, test::xyz(1, 2, 3), share * v, trial % 7, 1.0);
        const double ratio = test::worst_ratio(stop.samples, limits);
        ASSERT_LE(ratio, 1.0 + 1e-9) << "trial " << trial;
        worst = std::max(worst, ratio);
    }
    EXPECT_GT(whole, 50);
    EXPECT_GT(scaled, 50);
    EXPECT_GT(worst, 0.99);  // a scaled stop reaches a limit
}
