// dense_leg_flip() against the leg conditions it solves, tested point by point.
#include <firtp/dense_legs.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace firtp {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// The step from b u to a u' (a = min(b, n)) within both legs, as lookahead.cpp's dense_probe tests it.
bool fits(const DenseLegs& legs, double b, double n) {
    const double a = std::min(b, n);
    double t1 = 0.0;
    for (int k = 0; k < legs.axes; ++k)
        if (std::isfinite(legs.cap[k])) t1 = std::max(t1, std::abs(a * legs.u_next[k] - b * legs.u[k]) / legs.cap[k]);
    const double leg = b > 0.0 ? legs.length / b : infinity, next_leg = a > 0.0 ? legs.next_length / a : infinity;
    return !(t1 > leg || t1 > next_leg);
}

AxisVector direction(std::mt19937_64& rng, int axes) {
    std::normal_distribution<double> normal;
    AxisVector u = AxisVector::Zero();
    for (int k = 0; k < axes; ++k) u[k] = normal(rng);
    if (rng() % 4 == 0) u[rng() % axes] = 0.0;  // an axis that does not move
    return u / u.norm();
}

TEST(DenseLegs, FlipIsWhereTheLegConditionsFlip) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int found = 0, none = 0, none_braking = 0, braking_cases = 0;
    for (int c = 0; c < 20000; ++c) {
        const int axes = 2 + static_cast<int>(rng() % 2);
        const AxisVector u = direction(rng, axes);
        // Dense paths turn a little at each junction; some turn anywhere (reversals among them).
        const bool straight = c % 3 != 0;
        AxisVector u_next = straight ? AxisVector(u + 0.02 * unit(rng) * direction(rng, axes)) : direction(rng, axes);
        u_next /= u_next.norm();
        AxisVector cap = AxisVector::Constant(infinity);
        for (int k = 0; k < axes; ++k) cap[k] = rng() % 8 == 0 ? infinity : 5.0 + 5000.0 * unit(rng);
        const double length = 1e-3 * (0.001 + unit(rng)), next_length = 1e-3 * (0.001 + unit(rng));
        double n = c % 7 == 0 ? 0.0 : 200.0 * unit(rng) * unit(rng);
        const DenseLegs legs{u, u_next, cap, axes, length, next_length};
        // Braking along a dense run, the speed after passes the junction on its own (a block may
        // leave at the next one's bound); elsewhere the passing speeds need not be one interval.
        const bool braking = straight && c % 2 == 0;
        while (braking && !fits(legs, n, n)) n *= 0.5;
        const auto flip = dense_leg_flip(legs, n);
        braking_cases += braking;
        if (!flip) {
            ++none, none_braking += braking;
            continue;
        }
        ++found;
        ASSERT_GT(*flip, 0.0) << "case " << c;
        if (!std::isfinite(*flip)) {
            for (double b = 1e-3; b < 1e9; b *= 3.7) ASSERT_TRUE(fits(legs, b, n)) << "case " << c << " b " << b;
            continue;
        }
        const double below = *flip * (1.0 - 1e-9), above = *flip * (1.0 + 1e-9);
        ASSERT_TRUE(fits(legs, below, n)) << "case " << c << " flip " << *flip << " n " << n;
        ASSERT_FALSE(fits(legs, above, n)) << "case " << c << " flip " << *flip << " n " << n;
        // One interval from 0: every speed below passes, every one above (to 8 x) fails.
        for (int k = 1; k <= 64; ++k) {
            ASSERT_TRUE(fits(legs, below * k / 64.0, n)) << "case " << c << " at " << k << "/64 of the flip";
            ASSERT_FALSE(fits(legs, above * (1.0 + 7.0 * k / 64.0), n)) << "case " << c << " above the flip";
        }
    }
    std::printf("flip found %d, none %d (%d of %d braking along a dense run)\n", found, none, none_braking, braking_cases);
    EXPECT_LT(none_braking * 100, braking_cases);  // a guess nearly everywhere there
}

}  // namespace
}  // namespace firtp
