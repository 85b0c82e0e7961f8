// A block planned from rest ramps on above its start's speed where that fits, as it would once its
// start froze and it were planned again under way (lookahead.cpp, plan_segment). Where the check
// then refuses the corner after it, the block keeps its start's speed instead of that corner being
// lowered: two of firtp_cliffs' random programs (seed 99 program 1319, seed 7 program 486) ran
// 0.4 % and 1.2 % slower with the corner lowered than with one speed from rest.
//
// Since 2026-12-02 the check passes both ramps: their refusals were the limit sweep's rounding
// (a step of 3e-15 s between two legs jumped by +-2e16 mm/s^2 in acceleration, and the sum of
// those jumps came out 4 mm/s^2 over the limit: 1788 against 1786.99, 896 against 895.48). The
// sweep takes such a junction's two edges as one now (motion_check.cpp).
#include "support/random_machine.hpp"

#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <utility>

namespace firtp {
namespace {

// firtp_cliffs' program `program` of `seed`.
test::RandomCase cliffs_case(std::uint64_t seed, int program) {
    std::mt19937_64 rng(seed);
    for (int k = 0; k < program; ++k) test::cliffs_program(rng);
    return test::cliffs_program(rng).c;
}

TEST(StartRamp, RampsOnOnceRefusedByRoundingPassTheCheck) {
    for (const auto& [seed, program] : {std::pair<std::uint64_t, int>{99, 1319}, {7, 486}}) {
        const test::RandomCase c = cliffs_case(seed, program);
        const Trajectory t = plan_trajectory(c.parameters, AxisVector::Zero(), c.blocks);
        EXPECT_EQ(t.stats.checks_failed, 0u) << "seed " << seed << " program " << program << ": the ramp on was refused";
        for (const CornerReport& r : t.corners)
            EXPECT_NE(r.bound, CornerBound::checked) << "seed " << seed << " program " << program << " line " << r.line;
        ASSERT_FALSE(t.samples.empty());
        EXPECT_EQ(t.samples.back().position, c.blocks.back().target);
    }
}

}  // namespace
}  // namespace firtp
