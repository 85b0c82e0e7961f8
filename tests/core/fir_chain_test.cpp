// The chain in closed form against Eq. 4, 6, 9 and an independent truncated-power reference.
#include "support/reference.hpp"

#include <firtp/fir_chain.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

using namespace firtp;
using firtp::test::chain_of;

namespace {

const FilterTimes fractional_chains[] = {
    chain_of({0.0153}),
    chain_of({0.0153, 0.0071}),
    chain_of({0.0153, 0.0071, 0.00333}),
    chain_of({0.0153, 0.0071, 0.00333, 0.0011}),
    chain_of({0.148, 0.089}),
    chain_of({0.05, 0.05, 0.05}),  // repeated knots
};

}  // namespace

TEST(FirChain, PulseMatchesTruncatedPowerReferenceForFractionalTimes) {
    for (const FilterTimes& f : fractional_chains) {
        const FirChain chain(f);
        for (double tv : {0.0007, 0.003, 0.05, 2.7}) {
            for (int k = 0; k <= 4000; ++k) {
                const double t = (tv + f.delay()) * (k / 4000.0) * 1.02 - 0.001;
                const double expected = t >= tv + f.delay() ? 1.0
                                        : test::box_spline_progress(f, tv, t);
                ASSERT_NEAR(chain.pulse(t, tv).position, expected, 1e-12)
                    << "stages " << f.stages << " tv " << tv << " t " << t;
            }
        }
    }
}

TEST(FirChain, StepResponseIsContinuousMonotoneAndEndsAtHalfDelayLag) {
    for (const FilterTimes& f : fractional_chains) {
        const FirChain chain(f);
        const double td = chain.delay();
        double last_velocity = 0.0;
        for (int k = 1; k <= 20000; ++k) {
            const double t = td * k / 20000.0;
            const StepSample s = chain.step(t);
            ASSERT_GE(s.velocity, last_velocity - 1e-12);
            ASSERT_LE(s.velocity, 1.0 + 1e-12);
            last_velocity = s.velocity;
        }
        for (double t : {td, td + 0.3, td + 1e4}) EXPECT_DOUBLE_EQ(chain.step(t).position, t - td / 2);
        const StepSample before = chain.step(td * (1 - 1e-12));
        EXPECT_NEAR(before.position, td / 2, 1e-12);
        EXPECT_NEAR(before.velocity, 1.0, 1e-9);
    }
}

TEST(FirChain, Eq4OneStageTurnsThePulseIntoATrapezoid) {
    const double F = 50.0, T1 = 0.02, tv = 0.05, dt = 0.001;
    const FirChain chain(chain_of({T1}));
    double peak_acceleration = 0.0;
    for (int k = 0; k <= 100; ++k) {
        const double t = k * dt;
        const double v = F * chain.pulse(t, tv).velocity * tv;  // axis velocity of the F pulse
        const double expected = t < T1 ? F / T1 * t : t < tv ? F : t < tv + T1 ? F / T1 * (tv + T1 - t) : 0.0;
        EXPECT_NEAR(v, expected, 1e-9) << "t = " << t;
        peak_acceleration = std::max(peak_acceleration, std::abs(F * tv * chain.pulse(t, tv).acceleration));
    }
    EXPECT_NEAR(peak_acceleration, F / T1, 1e-9);  // a_max = v / T1
}

TEST(FirChain, TwoStagesLimitJerkToFOverT1T2) {
    const double F = 250.0, T1 = 0.148, T2 = 0.089, tv = 0.5;
    const FirChain chain(chain_of({T1, T2}));
    double peak_acceleration = 0.0, peak_jerk = 0.0;
    for (int k = 0; k <= 100000; ++k) {
        const double t = (tv + T1 + T2) * k / 100000.0;
        const StepSample s = chain.pulse(t, tv);
        peak_acceleration = std::max(peak_acceleration, std::abs(F * tv * s.acceleration));
        peak_jerk = std::max(peak_jerk, std::abs(F * tv * s.jerk));
    }
    EXPECT_NEAR(peak_acceleration, F / T1, 1e-6);
    EXPECT_NEAR(peak_jerk, F / (T1 * T2), 1e-6);
}

TEST(FirChain, Eq6MotionEndsExactlyOneDelayAfterThePulse) {
    for (const FilterTimes& f : fractional_chains) {
        const FirChain chain(f);
        EXPECT_DOUBLE_EQ(chain.delay(), f.T[0] + f.T[1] + f.T[2] + f.T[3]);
        const double tv = 0.031;
        const double just_before = tv + f.delay() - 0.25 * f.T[f.stages - 1];
        EXPECT_LT(chain.pulse(just_before, tv).position, 1.0 - 1e-12);
        EXPECT_GT(chain.pulse(just_before, tv).velocity, 0.0);
        EXPECT_NEAR(chain.pulse(tv + f.delay(), tv).position, 1.0, 1e-14);
        EXPECT_EQ(chain.pulse(tv + f.delay() + 1e-9, tv).velocity, 0.0);
    }
}

// |A(f)| of the impulse response, by the midpoint rule over [0, Td].
static double response_magnitude(const FirChain& chain, double frequency) {
    const int n = 200000;
    const double td = chain.delay(), h = td / n;
    std::complex<double> sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double t = (k + 0.5) * h;
        sum += chain.step(t).acceleration * std::exp(std::complex<double>(0.0, -2.0 * std::numbers::pi * frequency * t));
    }
    return std::abs(sum * h);
}

TEST(FirChain, Eq9ResponseIsAProductOfSincsWithZerosAtMultiplesOfOneOverTi) {
    const FilterTimes f = chain_of({0.148, 0.089});
    const FirChain chain(f);
    for (double frequency : {0.5, 3.0, 9.0, 20.0}) {
        double expected = 1.0;
        for (int i = 0; i < f.stages; ++i) {
            const double x = std::numbers::pi * frequency * f.T[i];
            expected *= std::abs(std::sin(x) / x);
        }
        EXPECT_NEAR(response_magnitude(chain, frequency), expected, 1e-6) << frequency << " Hz";
    }
    for (int i = 0; i < f.stages; ++i)
        for (int k = 1; k <= 3; ++k)
            EXPECT_LT(response_magnitude(chain, k / f.T[i]), 1e-6) << "zero k / T" << i + 1;
    EXPECT_GT(response_magnitude(chain, 0.5 / f.T[0]), 0.1);
}
