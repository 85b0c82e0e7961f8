// Cost per servo tick and per planned block. Run: build/bin/firtp_bench
// Counters: worst_ns is the slowest single call seen (a shared machine adds noise to it).
#include <firtp/interpolator.hpp>
#include <firtp/planner.hpp>

#include <benchmark/benchmark.h>

#include <chrono>
#include <random>

using namespace firtp;

namespace {

FilterTimes chain_with(int stages) {
    FilterTimes f;
    f.stages = stages;
    const double times[] = {0.148, 0.089, 0.031, 0.011};
    for (int i = 0; i < stages; ++i) f.T[i] = times[i];
    return f;
}

// Random corners in `axes` axes, 2-40 mm, 100-300 mm/s, 0.05 mm tolerance.
std::vector<Block> random_blocks(int axes, std::size_t count, bool varying_feed, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), length(2.0, 40.0), feed(100.0, 300.0);
    std::vector<Block> blocks(count);
    AxisVector at = AxisVector::Zero();
    for (std::size_t i = 0; i < count; ++i) {
        AxisVector d = AxisVector::Zero();
        for (int a = 0; a < axes; ++a) d[a] = unit(rng);
        at += d.normalized() * length(rng);
        blocks[i].target = at;
        blocks[i].feed = varying_feed ? feed(rng) : 250.0;
        blocks[i].tolerance = 0.05;
        blocks[i].line = static_cast<std::int64_t>(i + 1);
    }
    return blocks;
}

void BM_Tick(benchmark::State& state) {
    const int axes = static_cast<int>(state.range(0));
    PlannerParameters parameters;
    parameters.filters = chain_with(static_cast<int>(state.range(1)));
    const FirChain chain(parameters.filters);
    const std::vector<Block> blocks = random_blocks(axes, 4096, false, 1);
    Interpolator interpolator(chain, parameters.period, blocks.size(), AxisVector::Zero());
    Planner planner(parameters, chain, AxisVector::Zero());
    auto refill = [&] {
        interpolator.reset(AxisVector::Zero());
        planner.reset(AxisVector::Zero(), interpolator.now_tick());
        for (const Block& b : blocks) planner.add(b, interpolator);
    };
    refill();
    AxisState out;
    double worst = 0.0;
    for (auto _ : state) {
        if (interpolator.idle()) {
            state.PauseTiming();
            refill();
            state.ResumeTiming();
        }
        const auto begin = std::chrono::steady_clock::now();
        interpolator.tick(out);
        const auto end = std::chrono::steady_clock::now();
        worst = std::max(worst, std::chrono::duration<double, std::nano>(end - begin).count());
        benchmark::DoNotOptimize(out);
    }
    state.counters["worst_ns"] = worst;
}
BENCHMARK(BM_Tick)->ArgNames({"axes", "stages"})->Args({3, 2})->Args({3, 3})->Args({9, 2})->Args({9, 3})->Args({9, 4});

// Planning one block: Tk from the closed form (equal feeds) or from the corner model (feeds differ).
void BM_PlanBlock(benchmark::State& state) {
    PlannerParameters parameters;
    parameters.filters = chain_with(static_cast<int>(state.range(0)));
    const FirChain chain(parameters.filters);
    const std::vector<Block> blocks = random_blocks(3, 4096, state.range(1) != 0, 2);
    Interpolator interpolator(chain, parameters.period, blocks.size(), AxisVector::Zero());
    Planner planner(parameters, chain, AxisVector::Zero());
    std::size_t next = 0;
    double worst = 0.0;
    for (auto _ : state) {
        if (next == blocks.size()) {
            state.PauseTiming();
            interpolator.reset(AxisVector::Zero());
            planner.reset(AxisVector::Zero(), interpolator.now_tick());
            next = 0;
            state.ResumeTiming();
        }
        const auto begin = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(planner.add(blocks[next++], interpolator));
        const auto end = std::chrono::steady_clock::now();
        worst = std::max(worst, std::chrono::duration<double, std::nano>(end - begin).count());
    }
    state.counters["worst_ns"] = worst;
}
BENCHMARK(BM_PlanBlock)->ArgNames({"stages", "varying_feed"})->Args({2, 0})->Args({2, 1})->Args({3, 0})->Args({3, 1});

}  // namespace

BENCHMARK_MAIN();
