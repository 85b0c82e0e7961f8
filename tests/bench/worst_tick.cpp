// The servo tick's worst case over a long run: Planner::tick timed one call at a time.
//
//   firtp_worst_tick [--axes 3] [--chain --stages 2] [--ticks 10000000] [--seed 1] [--json]
//
// Machine: every axis 300 mm/s, 5000 mm/s^2, 1e5 mm/s^3, moves smoothed at the limits; with
// --chain the paper's fixed chain of --stages stages (T 148, 89, 31, 11 ms), no limits.
//
// Random moves keep the planner busy for the whole run: 0.05-40 mm (log-uniform, so short
// blocks overlap in the filter window), 50-300 mm/s, 0.01-0.1 mm tolerances, every 50th an exact
// stop. Blocks are planned between ticks (not timed). Each tick is timed with this thread's CPU
// clock and the wall clock; the wall clock's maxima include preemption by other jobs on a shared
// machine, the CPU clock's do not. The timers' own cost is measured on an empty body first
// ("floor") and is included in every figure. At the end the queue drains and the output must rest
// exactly (bit for bit) on the last command; exit status 1 otherwise.
#include "bench_stats.hpp"
#include "random_moves.hpp"

#include <firtp/planner.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace firtp;
using namespace firtp::bench;

namespace {

FilterTimes chain_with(int stages) {  // as firtp_bench (tests/bench/bench.cpp)
    FilterTimes f;
    f.stages = stages;
    const double times[] = {0.148, 0.089, 0.031, 0.011};
    for (int i = 0; i < stages; ++i) f.T[i] = times[i];
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    int axes = 3, stages = 2;
    long long ticks = 10'000'000;
    std::uint64_t seed = 1;
    bool json = false, chain = false;
    for (int i = 1; i < argc; ++i) {
        const bool has_value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--json")) json = true;
        else if (!std::strcmp(argv[i], "--chain")) chain = true;
        else if (!std::strcmp(argv[i], "--axes") && has_value) axes = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--stages") && has_value) stages = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--ticks") && has_value) ticks = std::atoll(argv[++i]);
        else if (!std::strcmp(argv[i], "--seed") && has_value) seed = std::strtoull(argv[++i], nullptr, 10);
        else {
            std::fprintf(stderr, "usage: %s [--axes 1-9] [--chain --stages 1-4] [--ticks N] [--seed S] [--json]\n", argv[0]);
            return 2;
        }
    }
    if (axes < 1 || axes > max_axes || stages < 1 || stages > max_stages || ticks < 1) {
        std::fprintf(stderr, "axes 1-9, stages 1-4, ticks >= 1\n");
        return 2;
    }

    PlannerParameters parameters;
    parameters.queue_capacity = 64;
    if (chain) {
        parameters.fixed_chain = true;
        parameters.filters = chain_with(stages);
    } else {
        parameters.limits.axes = axes;
        for (int a = 0; a < axes; ++a) parameters.limits.axis[a] = {300.0, 5000.0, 1e5};
    }
    Planner planner(parameters, AxisVector::Zero());
    RandomMoves moves(axes, seed);

    // The timers alone, on an empty body.
    Histogram floor_cpu, floor_wall;
    for (int i = 0; i < 100'000; ++i) {
        const std::int64_t c0 = thread_cpu_ns();
        const std::int64_t w0 = wall_ns();
        const std::int64_t w1 = wall_ns();
        const std::int64_t c1 = thread_cpu_ns();
        floor_wall.add(w1 - w0);
        floor_cpu.add(c1 - c0);
    }

    Histogram cpu, wall;
    AxisState out;
    AxisVector last_target = AxisVector::Zero();
    std::int64_t moving_ticks = 0;
    const std::int64_t begin = wall_ns();
    for (long long k = 0; k < ticks; ++k) {
        // Keep the queue fed: up to 4 blocks a period (short blocks can take less than a period).
        for (int i = 0; i < 4 && planner.free() > 0 && planner.depth() < 32; ++i) {
            const Block b = moves.next();
            if (refused(planner.add(b))) {
                std::fprintf(stderr, "block %lld refused\n", static_cast<long long>(b.line));
                return 1;
            }
            last_target = b.target;
        }
        moving_ticks += planner.idle() ? 0 : 1;
        const std::int64_t c0 = thread_cpu_ns();
        const std::int64_t w0 = wall_ns();
        planner.tick(out);
        const std::int64_t w1 = wall_ns();
        const std::int64_t c1 = thread_cpu_ns();
        wall.add(w1 - w0);
        cpu.add(c1 - c0);
    }
    const double seconds = static_cast<double>(wall_ns() - begin) * 1e-9;
    planner.finish();
    while (!planner.idle()) planner.tick(out);
    planner.tick(out);
    const bool exact = out.position == last_target && out.velocity == AxisVector::Zero();

    if (json) {
        std::printf("{\"axes\":%d,\"stages\":%d,\"ticks\":%lld,\"moving_ticks\":%lld,\"blocks\":%lld,\"seconds\":%.2f,"
                    "\"end_exact\":%s,\"cpu_ns\":%s,\"wall_ns\":%s,\"floor_cpu_ns\":%s,\"floor_wall_ns\":%s}\n",
                    axes, stages, ticks, static_cast<long long>(moving_ticks), static_cast<long long>(moves.count()),
                    seconds, exact ? "true" : "false", cpu.json().c_str(), wall.json().c_str(),
                    floor_cpu.json().c_str(), floor_wall.json().c_str());
    } else {
        std::printf("%d axes, %d stages: %lld ticks (%lld moving), %lld blocks, %.1f s\n", axes, stages, ticks,
                    static_cast<long long>(moving_ticks), static_cast<long long>(moves.count()), seconds);
        std::printf("  thread CPU clock: mean %.0f ns, p50 %lld, p99 %lld, p99.99 %lld, max %lld ns (timer floor p50 %lld)\n",
                    cpu.mean(), static_cast<long long>(cpu.quantile(0.5)), static_cast<long long>(cpu.quantile(0.99)),
                    static_cast<long long>(cpu.quantile(0.9999)), static_cast<long long>(cpu.max()),
                    static_cast<long long>(floor_cpu.quantile(0.5)));
        std::printf("  wall clock:       mean %.0f ns, p50 %lld, p99 %lld, p99.99 %lld, max %lld ns (timer floor p50 %lld; "
                    "maxima include preemption)\n",
                    wall.mean(), static_cast<long long>(wall.quantile(0.5)), static_cast<long long>(wall.quantile(0.99)),
                    static_cast<long long>(wall.quantile(0.9999)), static_cast<long long>(wall.max()),
                    static_cast<long long>(floor_wall.quantile(0.5)));
        std::printf("  end: %s\n", exact ? "exactly on the last command" : "NOT on the last command");
    }
    return exact ? 0 : 1;
}
