// The planning cost of one block, without this machine's noise: BM_PlanBlock's stream (random
// corners, 64 blocks of look-ahead, the built-in machine) planned --repeat times over. A block's
// cost is its add() and the servo ticks before it that planned (blocks added to a window that
// reaches far enough wait and join it in batches at a tick: lookahead_reach.cpp); ticks that plan
// nothing are BM_Tick's. Planning is deterministic, so block k costs the same work in every run;
// other jobs, interrupts and a VM's stolen time only ever add to it. Each block's least
// thread-CPU time over the runs is its own cost; this prints their mean, p99 and max, and the
// single-run figures beside; and the slowest single call (an add or a tick), the most a servo
// period spends planning.
//
//   firtp_worst_add [--blocks 20000] [--repeat 7] [--seed 2] [--varying-feed]
//
// Memory: one double per add (a benchmark, not the planner).
#include "bench_stats.hpp"
#include "random_corners.hpp"

#include <firtp/planner.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace firtp;

namespace {

struct Figures {
    double mean = 0.0, p99 = 0.0, max = 0.0;
    std::size_t worst = 0;  // the add with the max (0-based)
};

Figures figures(const std::vector<double>& us) {
    Figures f;
    std::vector<double> sorted = us;
    std::sort(sorted.begin(), sorted.end());
    for (double x : us) f.mean += x;
    f.mean /= static_cast<double>(us.size());
    f.p99 = sorted[sorted.size() * 99 / 100];
    f.max = sorted.back();
    f.worst = static_cast<std::size_t>(std::max_element(us.begin(), us.end()) - us.begin());
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    long blocks = 20000;
    int repeat = 7;
    std::uint64_t seed = 2;
    bool varying = false;
    for (int i = 1; i < argc; ++i) {
        const bool has_value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--blocks") && has_value) blocks = std::atol(argv[++i]);
        else if (!std::strcmp(argv[i], "--repeat") && has_value) repeat = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--seed") && has_value) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(argv[i], "--varying-feed")) varying = true;
        else {
            std::fprintf(stderr, "usage: %s [--blocks N] [--repeat K] [--seed S] [--varying-feed]\n", argv[0]);
            return 2;
        }
    }
    if (blocks < 100 || repeat < 1) {
        std::fprintf(stderr, "firtp_worst_add: --blocks >= 100 and --repeat >= 1\n");
        return 2;
    }
    const PlannerParameters parameters = bench::machine(true, 3, 2);  // BM_PlanBlock's limits:1

    const auto n = static_cast<std::size_t>(blocks);
    std::vector<double> least(n, HUGE_VAL), first(n, 0.0), call_least(n, HUGE_VAL), call_first(n, 0.0);
    for (int run = 0; run < repeat; ++run) {
        Planner planner(parameters, AxisVector::Zero());
        bench::RandomCorners corners(3, varying, seed);
        AxisState out;
        for (std::size_t k = 0; k < n; ++k) {
            const bench::PlanningTicks ticks = bench::tick_until_room(planner, out, bench::thread_cpu_ns);
            double spent = ticks.total_ns * 1e-3, slowest = ticks.slowest_ns * 1e-3;
            const Block block = corners.next();
            const std::int64_t c0 = bench::thread_cpu_ns();
            const Result result = planner.add(block);
            const std::int64_t c1 = bench::thread_cpu_ns();
            if (result != Result::ok) {
                std::fprintf(stderr, "firtp_worst_add: block %zu not planned\n", k + 1);
                return 1;
            }
            const double us = static_cast<double>(c1 - c0) * 1e-3;
            spent += us;
            slowest = std::max(slowest, us);
            least[k] = std::min(least[k], spent);
            call_least[k] = std::min(call_least[k], slowest);
            if (run == 0) first[k] = spent, call_first[k] = slowest;
        }
    }
    const Figures once = figures(first), own = figures(least);
    const Figures call_once = figures(call_first), call_own = figures(call_least);
    std::printf("%ld blocks (random corners, %s feeds, seed %llu), thread CPU clock, us a block (its add and the ticks that planned before it)\n",
                blocks, varying ? "100-300 mm/s" : "equal", static_cast<unsigned long long>(seed));
    std::printf("  one run:             mean %.2f  p99 %.1f  max %.1f (block %zu)\n", once.mean, once.p99, once.max, once.worst + 1);
    std::printf("  least of %d runs:     mean %.2f  p99 %.1f  max %.1f (block %zu)\n", repeat, own.mean, own.p99, own.max, own.worst + 1);
    std::printf("  slowest single call (an add or a tick): one run %.1f, least of %d runs %.1f (block %zu)\n", call_once.max, repeat,
                call_own.max, call_own.worst + 1);
    return 0;
}
