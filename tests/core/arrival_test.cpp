// lookahead.hpp: "the motion does not depend on when blocks arrive, only on which". Random
// programs fed a few blocks a period, as firtp.so and firtp_tp take them, against the whole
// program known at once (programs that fit the window: a full window commits when it fills).
//
// DISABLED: a known defect, found 2026-11-27 and not fixed. It fails on 8 of 14 seeds
// (FIRTP_RANDOM_SEED 1, 2, 3, 5, 7, 12, 13, 14) with 1 or 2 blocks a period (FIRTP_PER_PERIOD), e.g. seed 1
// program 48: 34 blocks, all known by tick 17, the motions part at tick 107 and the fed one ends
// 27 periods later. Found: the first block's start step freezes once its exit bound is its own
// (final_for_start), with 2 blocks known; but the second block's classification (dense or not)
// depends on the junction after it, and with it the first junction's regime and so the first
// block's speed (seed 2 program 20: 32.61 mm/s fed, 33.90 known at once). Requiring more blocks
// before a start (or a real stop among them) removes most: of seeds 1-14, 6 pass now, 11 with 2
// more blocks, 13 with 4 (not seed 13 program 148), 10 waiting until the runs of short blocks at
// the first two blocks end known; a rule that follows every dependence of the start is needed.
// Run it with
//   FIRTP_RANDOM_SEED=1 FIRTP_PER_PERIOD=2 core_tests --gtest_also_run_disabled_tests --gtest_filter='Arrival.*'
#include "support/random_machine.hpp"

#include <firtp/planner.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace firtp {
namespace {

std::vector<AxisState> fed_per_period(const PlannerParameters& p, const std::vector<Block>& blocks, int per_period) {
    Planner planner(p, AxisVector::Zero());
    std::vector<AxisState> out;
    PlannerInput input;
    PlannerOutput period;
    std::size_t next = 0;
    for (Result motion = Result::working; motion == Result::working || next < blocks.size();) {
        for (int k = 0; k < per_period && next < blocks.size(); ++k) {
            if (planner.add(blocks[next]) == Result::queue_full) break;
            ++next;
        }
        input.end_of_program = next == blocks.size();
        motion = planner.update(input, period);
        out.push_back(period.state);
        if (out.size() > 20'000'000) break;
    }
    return out;
}

TEST(Arrival, DISABLED_BlocksFedAFewAPeriodGiveTheSamplesOfTheWholeProgram) {
    const char* seed = std::getenv("FIRTP_RANDOM_SEED");
    const char* per = std::getenv("FIRTP_PER_PERIOD");
    const int per_period = per ? std::atoi(per) : 2;
    std::mt19937_64 rng(seed ? std::strtoull(seed, nullptr, 10) : 1);
    int compared = 0;
    for (int program = 0; program < 200; ++program) {
        const PlannerParameters p = test::random_machine(rng);
        const std::vector<Block> blocks = test::random_blocks(rng, p);
        if (blocks.size() >= p.queue_capacity) continue;
        const Trajectory whole = plan_trajectory(p, AxisVector::Zero(), blocks);
        const std::vector<AxisState> fed = fed_per_period(p, blocks, per_period);
        // A first block alone waits for the next before it starts: the same motion, later.
        auto first_move = [](const std::vector<AxisState>& s) {
            std::size_t k = 0;
            while (k < s.size() && s[k].position == AxisVector::Zero()) ++k;
            return k;
        };
        const std::size_t a = first_move(whole.samples), b = first_move(fed);
        ASSERT_GE(b, a);
        ASSERT_EQ(fed.size() - b, whole.samples.size() - a) << "program " << program << " started " << b - a << " later";
        double scale = 1.0;
        for (const Block& block : blocks) scale = std::max(scale, block.target.cwiseAbs().maxCoeff());
        for (std::size_t k = a; k < whole.samples.size(); ++k)  // (later: times round differently)
            ASSERT_LE((fed[k + b - a].position - whole.samples[k].position).cwiseAbs().maxCoeff(), 1e-9 * scale)
                << "program " << program << " tick " << k << " of " << whole.samples.size();
        ++compared;
    }
    EXPECT_GT(compared, 100);
}

}  // namespace
}  // namespace firtp
