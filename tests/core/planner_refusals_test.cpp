// Blocks the planner must refuse rather than plan: a pulse Tv = L / F that does not fit the servo
// clock. fuzz_lcm found a block with feed 1e-300 (finite and positive, so it passed every check)
// whose Tv = inf reached a conversion to a tick count: undefined behaviour (UBSan: 'inf is
// outside the range of representable values of type long').
#include "support/reference.hpp"

#include <firtp/interpolator.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <limits>

using namespace firtp;

TEST(PlannerRefusals, PulseLongerThanTheClockIsRefusedAndNothingChanges) {
    PlannerParameters p;
    p.filters = test::chain_of({0.02, 0.01});
    const FirChain chain(p.filters);
    Interpolator interpolator(chain, p.period, 16, AxisVector::Zero());
    Planner planner(p, chain, AxisVector::Zero());
    Block b;
    b.target[0] = 10.0;
    b.tolerance = 0.05;
    for (double feed : {1e-300, std::numeric_limits<double>::denorm_min(), 1e-13}) {
        b.feed = feed;  // 10 mm: Tv = 1e301 s, inf, 1e14 s (the limit: 1e16 periods, 1e13 s at 1 ms)
        EXPECT_EQ(planner.add(b, interpolator), Result::invalid_block) << feed;
        EXPECT_TRUE(interpolator.idle());
    }
    b.target[0] = std::numeric_limits<double>::max();  // finite, but the length from -max overflows
    b.feed = 100.0;
    Block from = b;
    from.target[0] = -std::numeric_limits<double>::max();
    Planner far(p, chain, from.target);
    EXPECT_EQ(far.add(b, interpolator), Result::invalid_block);
    b.target[0] = 10.0;
    b.feed = 1e-9;  // 1e10 s, 1e13 periods: slow, but it fits
    EXPECT_EQ(planner.add(b, interpolator), Result::ok);
    EXPECT_EQ(interpolator.depth(), 1u);
}
