// Cost per servo tick and per planned block. Run: build/bin/firtp_bench
// Counters: worst_ns is the slowest single call seen (a shared machine adds noise to it; ticks:
// every 32nd call is timed for it).
//
// Machines: bench::machine (random_corners.hpp), "limits" the built-in machine's axes smoothed at
// their limits, otherwise the paper's fixed chain with as many stages as asked.
#include "random_corners.hpp"

#include <firtp/planner.hpp>

#include <benchmark/benchmark.h>

#include <chrono>

using namespace firtp;
using firtp::bench::machine;
using firtp::bench::RandomCorners;

namespace {

// `count` of firtp::bench::RandomCorners (random_corners.hpp).
std::vector<Block> random_blocks(int axes, std::size_t count, bool varying_feed, std::uint64_t seed) {
    RandomCorners corners(axes, varying_feed, seed);
    std::vector<Block> blocks(count);
    for (Block& b : blocks) b = corners.next();
    return blocks;
}

// A servo tick while moving through random corners: Planner::update, the call every user makes
// each period (settling what starts, then the state).
void BM_Tick(benchmark::State& state) {
    const bool limits = state.range(0) != 0;
    const int axes = static_cast<int>(state.range(1));
    const PlannerParameters parameters = machine(limits, axes, static_cast<int>(state.range(2)));
    const std::vector<Block> blocks = random_blocks(axes, 4096, false, 1);
    Planner planner(parameters, AxisVector::Zero());
    std::size_t next = 0;
    AxisState out;
    const PlannerInput input;
    PlannerOutput output;
    double worst = 0.0;
    std::uint64_t calls = 0;
    for (auto _ : state) {
        if (planner.depth() < 64) {  // keep the look-ahead fed, outside the timing
            state.PauseTiming();
            for (int k = 0; k < 64 && planner.free() > 0; ++k) {
                if (next == blocks.size()) {
                    while (!planner.idle()) planner.tick(out);
                    planner.reset(AxisVector::Zero());
                    next = 0;
                }
                planner.add(blocks[next++]);
            }
            state.ResumeTiming();
        }
        // Every 32nd call timed on its own for worst_ns (the clock costs a quarter of a tick).
        if ((++calls & 31) == 0) {
            const auto begin = std::chrono::steady_clock::now();
            planner.update(input, output);
            const auto end = std::chrono::steady_clock::now();
            worst = std::max(worst, std::chrono::duration<double, std::nano>(end - begin).count());
        } else {
            planner.update(input, output);
        }
        benchmark::DoNotOptimize(output);
    }
    state.counters["worst_ns"] = worst;
}
BENCHMARK(BM_Tick)
    ->ArgNames({"limits", "axes", "stages"})
    ->Args({1, 3, 2})
    ->Args({1, 9, 2})
    ->Args({0, 3, 2})
    ->Args({0, 3, 3})
    ->Args({0, 9, 2})
    ->Args({0, 9, 4});

// Planning one block as a stream arrives: add() with 64 blocks of look-ahead before it, and the
// servo ticks that plan blocks (blocks added to a window that reaches far enough wait, and join
// it in batches at a tick: lookahead_reach.cpp). Ticks that plan nothing run outside the timing
// (BM_Tick's). worst_ns: the slowest add or planning tick.
void BM_PlanBlock(benchmark::State& state) {
    const bool limits = state.range(0) != 0;
    const PlannerParameters parameters = machine(limits, 3, static_cast<int>(state.range(1)));
    const std::vector<Block> blocks = random_blocks(3, 4096, state.range(2) != 0, 2);
    Planner planner(parameters, AxisVector::Zero());
    std::size_t next = 0;
    AxisState out;
    double worst = 0.0;
    auto now = [] { return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now().time_since_epoch()).count(); };
    for (auto _ : state) {
        if (next == blocks.size()) {
            planner.finish();
            while (!planner.idle()) planner.tick(out);
            planner.reset(AxisVector::Zero());
            next = 0;
        }
        const firtp::bench::PlanningTicks ticks = firtp::bench::tick_until_room(planner, out, now);
        const double begin = now();
        benchmark::DoNotOptimize(planner.add(blocks[next++]));
        const double add = now() - begin;
        worst = std::max({worst, ticks.slowest_ns, add});
        state.SetIterationTime((ticks.total_ns + add) * 1e-9);
    }
    state.counters["worst_ns"] = worst;
}
BENCHMARK(BM_PlanBlock)
    ->ArgNames({"limits", "stages", "varying_feed"})
    ->Args({1, 2, 0})
    ->Args({1, 2, 1})
    ->Args({0, 2, 0})
    ->Args({0, 2, 1})
    ->Args({0, 3, 0})
    ->Args({0, 3, 1})
    ->UseManualTime();

}  // namespace

BENCHMARK_MAIN();
