// Blocks beyond the window's reach wait and join it in batches (lookahead_reach.cpp): an add to a
// window that already reaches four stops ahead waits, and the motion, measured on the samples,
// keeps its limits (also in finite differences), every corner within its tolerance and the exact
// end. Long random programs on random machines, with and without rate changes; seeded,
// FIRTP_RANDOM_SEED shifts the seed and FIRTP_RANDOM_SCALE soaks.
#include "support/chords.hpp"
#include "support/random_machine.hpp"
#include "support/rate_run.hpp"
#include "support/sampled_limits.hpp"

#include <firtp/measure.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace firtp;
using test::run_ticks;

namespace {

// Programs of 200-500 blocks (support/random_machine.hpp: long_random_case) on windows of 64, 256
// or 1024 blocks, all added as the window takes them, each planned as it comes (Planning::now, as
// firtp_tp and firtp.so add); every other one with six rate changes, holds among them, then 100 %.
void check_long_programs(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed + test::random_seed_offset());
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int programs = test::random_scaled(count);
    int waited = 0;
    for (int k = 0; k < programs; ++k) {
        test::RandomCase c = test::long_random_case(rng, 200 + rng() % 300);
        PlannerParameters& p = c.parameters;
        p.queue_capacity = std::array<std::size_t, 3>{64, 256, 1024}[rng() % 3];
        std::vector<std::pair<int, double>> rates;
        if (k % 2 == 1) {
            int tick = 0;
            for (int e = 0; e < 6; ++e) {
                tick += 1 + static_cast<int>(unit(rng) * 1.0 / p.period);
                rates.emplace_back(tick, unit(rng) < 0.25 ? 0.0 : p.max_rate * (0.1 + 0.9 * unit(rng)));
            }
            rates.emplace_back(tick + 1 + static_cast<int>(unit(rng) * 1.0 / p.period), 1.0);
        }
        SCOPED_TRACE("program " + std::to_string(k) + " (" + std::to_string(c.blocks.size()) + " blocks, queue " +
                     std::to_string(p.queue_capacity) + ")");
        const test::RateRun r = test::run_with_rates(p, c.blocks, rates, run_ticks(p));
        test::expect_within_random(r, c.blocks, p);
        if (r.stats.rejoined > 0) ++waited;
    }
    std::printf("%d long programs, blocks waited beyond the window in %d\n", programs, waited);
    EXPECT_GT(waited, programs / 2);  // the waiting is what this measures
}

}  // namespace

// On a dense path each block planned as it came planned again the blocks braking to the stop at
// the end of the path it ended (44 of them at jerk 1e5, 130 us an add). Added to a window that
// reaches four stops ahead, blocks wait and join up to 16 at a time under one plan. Counted in segment
// plans, not timed (firtp_worst_override times them).
TEST(Reach, BlocksBeyondTheReachJoinInBatchesNotOneByOne) {
    const PlannerParameters machine = test::deep_queue_machine();
    const std::vector<Block> program = test::helix_chords(3600);
    const test::RateRun r = test::run_with_rates(machine, program, {}, run_ticks(machine));
    test::expect_within(r, program, machine);
    const double per_block = static_cast<double>(r.stats.segments_planned) / static_cast<double>(program.size());
    std::printf("%zu chords: %.1f segment plans a block, %llu blocks waited, joins took %llu later steps\n", program.size(),
                per_block, static_cast<unsigned long long>(r.stats.rejoined), static_cast<unsigned long long>(r.stats.join_steps));
    EXPECT_GT(r.stats.rejoined, 3000u);
    EXPECT_GT(r.stats.join_steps, 200u);  // under way, a join takes a step a period
    EXPECT_LT(per_block, 10.0);
}

TEST(Reach, LongRandomPrograms) { check_long_programs(91, 16); }
