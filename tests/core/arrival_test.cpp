// lookahead.hpp: "the motion does not depend on when blocks arrive, only on which". Random
// programs fed a few blocks a period, as firtp.so and firtp_tp take them, against the whole
// program known at once (programs that fit the window: a full window commits when it fills).
//
// DISABLED: a known defect, found 2026-11-27, narrowed 2026-11-28. A start used to freeze with two
// blocks known, while the junction after its block is decided again when the block after next
// comes (classify, junction_caps); it now waits until that junction is settled
// (Lookahead::settled; AStartWaitsUntilTheJunctionAfterItsBlockIsSettled below). Seeds 1-14 that
// pass, 2 blocks a period: 6 before, 12 now (not seed 5 program 110, seed 7 program 147); 1 block
// a period: 10 now (also not seed 3 program 78, seed 12 program 124). Causes seen in what is left:
// the block under way is planned again after its start froze, and with its entry fixed its plateau
// may rise above the start's speed, which a plan from rest never does (seed 7 program 147: 55.49
// against 52.04 mm/s); and a check refused a plan only when fed, ending in a forced stop where the
// whole program passes the corner at 0.07 mm/s (seed 5 program 110).
// Run it with
//   FIRTP_RANDOM_SEED=1 FIRTP_PER_PERIOD=2 core_tests --gtest_also_run_disabled_tests --gtest_filter='Arrival.*'
#include "support/random_machine.hpp"

#include <firtp/planner.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <algorithm>
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

// Fed and known at once, programs `wanted` of the random programs from `seed` (all that fit the
// window if empty) must give the same samples; returns how many were compared.
int compare_fed_and_whole(std::uint64_t seed, int per_period, const std::vector<int>& wanted) {
    std::mt19937_64 rng(seed);
    int compared = 0;
    const int programs = wanted.empty() ? 200 : wanted.back() + 1;
    for (int program = 0; program < programs; ++program) {
        const PlannerParameters p = test::random_machine(rng);
        const std::vector<Block> blocks = test::random_blocks(rng, p);
        if (blocks.size() >= p.queue_capacity) continue;
        if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), program) == wanted.end()) continue;
        const Trajectory whole = plan_trajectory(p, AxisVector::Zero(), blocks);
        const std::vector<AxisState> fed = fed_per_period(p, blocks, per_period);
        // A first block alone waits for the next before it starts: the same motion, later.
        auto first_move = [](const std::vector<AxisState>& s) {
            std::size_t k = 0;
            while (k < s.size() && s[k].position == AxisVector::Zero()) ++k;
            return k;
        };
        const std::size_t a = first_move(whole.samples), b = first_move(fed);
        EXPECT_GE(b, a) << "seed " << seed << " program " << program;
        EXPECT_EQ(fed.size() - b, whole.samples.size() - a) << "seed " << seed << " program " << program << " started " << b - a << " later";
        if (b < a || fed.size() - b != whole.samples.size() - a) return compared;
        double scale = 1.0;
        for (const Block& block : blocks) scale = std::max(scale, block.target.cwiseAbs().maxCoeff());
        for (std::size_t k = a; k < whole.samples.size(); ++k) {  // (later: times round differently)
            const double off = (fed[k + b - a].position - whole.samples[k].position).cwiseAbs().maxCoeff();
            if (off > 1e-9 * scale) {
                ADD_FAILURE() << "seed " << seed << " program " << program << " tick " << k << " of " << whole.samples.size() << ": " << off << " mm apart";
                return compared;
            }
        }
        ++compared;
    }
    return compared;
}

TEST(Arrival, DISABLED_BlocksFedAFewAPeriodGiveTheSamplesOfTheWholeProgram) {
    const char* seed = std::getenv("FIRTP_RANDOM_SEED");
    const char* per = std::getenv("FIRTP_PER_PERIOD");
    EXPECT_GT(compare_fed_and_whole(seed ? std::strtoull(seed, nullptr, 10) : 1, per ? std::atoi(per) : 2, {}), 100);
}

// A start froze with two blocks known, but the junction after its block is decided again when the
// block after next comes (seed 2 program 20: 32.61 mm/s fed, 33.90 known at once). These failed
// before the start waited for its junction to settle.
TEST(Arrival, AStartWaitsUntilTheJunctionAfterItsBlockIsSettled) {
    EXPECT_EQ(compare_fed_and_whole(1, 2, {48}), 1);
    EXPECT_EQ(compare_fed_and_whole(2, 2, {20}), 1);
    EXPECT_EQ(compare_fed_and_whole(3, 2, {46}), 1);
}

}  // namespace
}  // namespace firtp
