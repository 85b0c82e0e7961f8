// Blocks the planner must refuse rather than plan: a pulse Tv = L / F that does not fit the servo
// clock. fuzz_lcm found a block with feed 1e-300 (finite and positive, so it passed every check)
// whose Tv = inf reached a conversion to a tick count: undefined behaviour (UBSan: 'inf is
// outside the range of representable values of type long').
#include "support/limits.hpp"
#include "support/reference.hpp"

#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <limits>

using namespace firtp;

TEST(PlannerRefusals, PulseLongerThanTheClockIsRefusedAndNothingChanges) {
    PlannerParameters p;
    p.fixed_chain = true;
    p.filters = test::chain_of({0.02, 0.01});
    Planner planner(p, AxisVector::Zero());
    Block b;
    b.target[0] = 10.0;
    b.tolerance = 0.05;
    for (double feed : {1e-300, std::numeric_limits<double>::denorm_min(), 1e-13}) {
        b.feed = feed;  // 10 mm: Tv = 1e301 s, inf, 1e14 s (the limit: 1e16 periods, 1e13 s at 1 ms)
        EXPECT_EQ(planner.add(b), Result::invalid_block) << feed;
        EXPECT_TRUE(planner.idle());
    }
    b.target[0] = std::numeric_limits<double>::max();  // finite, but the length from -max overflows
    b.feed = 100.0;
    Block from = b;
    from.target[0] = -std::numeric_limits<double>::max();
    Planner far(p, from.target);
    EXPECT_EQ(far.add(b), Result::invalid_block);
    b.target[0] = 10.0;
    b.feed = 1e-9;  // 1e10 s, 1e13 periods: slow, but it fits
    EXPECT_EQ(planner.add(b), Result::ok);
    EXPECT_EQ(planner.depth(), 1u);
    EXPECT_EQ(planner.add(b), Result::skipped);  // zero length, in the paper's mode too
    EXPECT_EQ(planner.depth(), 1u);
}

TEST(PlannerRefusals, AtTheLimitsValuesThatCannotWorkAreRefused) {
    PlannerParameters p;
    p.limits = test::uniform_limits(300.0, 5000.0, 1e5);
    Planner planner(p, AxisVector::Zero());
    Block b;
    b.target[0] = 10.0;
    b.tolerance = 0.05;
    for (double feed : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        b.feed = feed;
        EXPECT_EQ(planner.add(b), Result::invalid_block) << feed;
    }
    b.feed = 100.0;
    b.tolerance = 0.0;  // blending needs a tolerance
    EXPECT_EQ(planner.add(b), Result::invalid_block);
    b.tolerance = 0.05;
    b.target[1] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(planner.add(b), Result::invalid_block);
    EXPECT_TRUE(planner.idle());
    // An axis without an acceleration limit is one the machine does not have: a block that moves
    // it is refused, with the axis named; the others still plan.
    p.limits.axis[1].max_acceleration = 0.0;
    Planner without_y(p, AxisVector::Zero());
    b.target[1] = 5.0;
    EXPECT_EQ(without_y.add(b), Result::absent_axis);
    EXPECT_STREQ(without_y.refusal(), "moves Y, an axis the machine does not have (no acceleration limit)");
    b.target[1] = 0.0;
    b.target[6] = 1.0;  // U: beyond the machine's axes
    EXPECT_EQ(without_y.add(b), Result::absent_axis);
    EXPECT_STREQ(without_y.refusal(), "moves U, an axis the machine does not have (no acceleration limit)");
    b.target[6] = 0.0;
    EXPECT_EQ(without_y.add(b), Result::ok);
    EXPECT_EQ(without_y.accepted(), 1u);
    EXPECT_EQ(without_y.add(b), Result::skipped);  // already there: nothing to plan, nothing counted
    EXPECT_EQ(without_y.accepted(), 1u);
    for (int a = 0; a < 3; ++a) p.limits.axis[a].max_acceleration = 0.0;  // nothing to smooth at
    EXPECT_THROW(Planner(p, AxisVector::Zero()), std::invalid_argument);
    p.limits.axis[0].max_acceleration = -1.0;
    EXPECT_THROW(Planner(p, AxisVector::Zero()), std::invalid_argument);
}
