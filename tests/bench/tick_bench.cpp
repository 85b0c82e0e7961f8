// Worst-case time per servo tick over a long run: firtp's servo-thread function body
// (ComponentLogic::update: planning on acceptance, the FIR chain, status) driven by random programs
// with overrides, holds, aborts and stream faults (tests/realtime/random_operation.hpp).
//
//   build/bin/firtp_tick_bench [--ticks N] [--runs R] [--seed S] [--machine limits|free]
//                              [--blocks-per-tick K] [--fifo]
//
// Every tick is timed (CLOCK_MONOTONIC around the call). On a shared, non-real-time machine the
// slowest single tick measures the scheduler as much as the code, so the run is repeated R times
// (it is deterministic: same inputs, same work) and each tick keeps its fastest time: the worst of
// those minima is the slowest code path, with preemption filtered out. Reported separately for ticks
// that planned stream blocks and ticks that only interpolated. The stream gets K blocks before
// each period (default 1: every planning tick plans one block, so the worst tick is the worst
// single block; a larger K makes ticks plan up to max_blocks_per_period = 32 blocks, which
// `firtp serve` bounds with its planning budget, plan_budget_us: at least one block, more while
// the budget lasts). No budget here, so that runs repeat exactly. --fifo asks for SCHED_FIFO 80 and
// mlockall (root, or CAP_SYS_NICE / RLIMIT_RTPRIO), as a real-time servo thread has.
#include "random_operation.hpp"

#include <sched.h>
#include <sys/mman.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace firtp;

namespace {

std::int64_t now_ns() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

struct Run {
    std::vector<std::int32_t> ns;          // per tick
    std::vector<std::uint8_t> planned;     // blocks read from the stream in that tick
    test::OperationStats stats;
};

Run run_once(const ComponentSettings& settings, std::uint64_t seed, std::int64_t ticks, int per_tick) {
    Run r;
    r.ns.resize(static_cast<std::size_t>(ticks));
    r.planned.resize(static_cast<std::size_t>(ticks));
    ComponentLogic core(settings);
    test::StreamRing ring;
    test::OperationOptions options;
    options.blocks_per_tick = per_tick;
    test::RandomOperation op(settings, seed, options);
    ComponentOutputs out;
    for (std::int64_t k = 0; k < ticks; ++k) {
        op.before_tick(ring);
        const std::size_t before = ring.count;
        const std::int64_t t0 = now_ns();
        core.update(op.inputs(), ring.source(), out);
        const std::int64_t t1 = now_ns();
        r.ns[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(std::min<std::int64_t>(t1 - t0, INT32_MAX));
        r.planned[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(std::min<std::size_t>(before - ring.count, 255));
        op.after_tick(out, ring);
    }
    r.stats = op.stats();
    return r;
}

struct Summary {
    std::size_t n = 0;
    double median = 0, p99 = 0, p999 = 0, p9999 = 0, max = 0;
    std::size_t worst_tick = 0;
};

Summary summarise(const std::vector<std::int32_t>& ns, const std::vector<std::uint8_t>& planned, int which) {
    std::vector<std::int32_t> v;
    Summary s;
    std::int32_t worst = -1;
    for (std::size_t k = 0; k < ns.size(); ++k) {
        const bool p = planned[k] > 0;
        if (which == 1 && !p) continue;
        if (which == 2 && p) continue;
        if (which == 3 && planned[k] != 1) continue;
        v.push_back(ns[k]);
        if (ns[k] > worst) worst = ns[k], s.worst_tick = k;
    }
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    auto at = [&](double q) { return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))] / 1000.0; };
    s.n = v.size();
    s.median = at(0.5);
    s.p99 = at(0.99);
    s.p999 = at(0.999);
    s.p9999 = at(0.9999);
    s.max = v.back() / 1000.0;
    return s;
}

void print(const char* label, const Summary& s) {
    std::printf("  %-34s %9zu ticks  median %7.2f  p99 %7.2f  p99.9 %7.2f  p99.99 %7.2f  max %8.2f us (tick %zu)\n", label,
                s.n, s.median, s.p99, s.p999, s.p9999, s.max, s.worst_tick);
}

}  // namespace

int main(int argc, char** argv) {
    std::int64_t ticks = 3'600'000;  // one hour of motion at 1 kHz
    int runs = 3, per_tick = 1;
    std::uint64_t seed = 1;
    bool limits = true, fifo = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (a == "--ticks") ticks = static_cast<std::int64_t>(std::stod(value()));
        else if (a == "--runs") runs = std::max(1, std::stoi(value()));
        else if (a == "--seed") seed = std::stoull(value());
        else if (a == "--machine") limits = value() != "free";
        else if (a == "--blocks-per-tick") per_tick = std::max(1, std::stoi(value()));
        else if (a == "--fifo") fifo = true;
        else {
            std::fprintf(stderr, "usage: firtp_tick_bench [--ticks N] [--runs R] [--seed S] [--machine limits|free] "
                                 "[--blocks-per-tick K] [--fifo]\n");
            return a == "--help" ? 0 : 2;
        }
    }
    if (fifo) {
        sched_param sp{};
        sp.sched_priority = 80;
        const bool rt = sched_setscheduler(0, SCHED_FIFO, &sp) == 0;
        const bool locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
        std::printf("SCHED_FIFO %s, mlockall %s\n", rt ? "on" : "refused", locked ? "on" : "refused");
    }
    const ComponentSettings settings = test::operation_settings(limits);
    std::printf("firtp_tick_bench: ComponentLogic::update, %s, %lld ticks (%.2f h of motion at %.0f Hz), seed %llu, %d runs, up to %d blocks "
                "into the stream a period\n",
                limits ? "built-in machine with limits (300 mm/s, 5000 mm/s^2, 1e5 mm/s^3), override up to 150 %"
                       : "T1 148 / T2 89 ms, no limits",
                static_cast<long long>(ticks), static_cast<double>(ticks) * settings.planner.period / 3600.0,
                1.0 / settings.planner.period, static_cast<unsigned long long>(seed), runs, per_tick);

    std::vector<std::int32_t> best;
    std::vector<std::uint8_t> planned;
    test::OperationStats stats;
    for (int r = 0; r < runs; ++r) {
        Run one = run_once(settings, seed, ticks, per_tick);
        if (one.stats.violations > 0) {
            std::fprintf(stderr, "check failed: %s\n", one.stats.first_violation);
            return 1;
        }
        if (r == 0) {
            std::printf("run 1 (single run, as timed):\n");
            print("every tick", summarise(one.ns, one.planned, 0));
            best = one.ns;
            planned = one.planned;
            stats = one.stats;
        } else {
            for (std::size_t k = 0; k < best.size(); ++k) best[k] = std::min(best[k], one.ns[k]);
            if (one.planned != planned) {
                std::fprintf(stderr, "runs differ: the benchmark is not deterministic\n");
                return 1;
            }
        }
    }
    std::printf("fastest of %d runs per tick (the code's own time; preemption filtered out):\n", runs);
    print("every tick", summarise(best, planned, 0));
    print("ticks that planned stream blocks", summarise(best, planned, 1));
    print("ticks that planned exactly one", summarise(best, planned, 3));
    print("ticks that only interpolated", summarise(best, planned, 2));
    int most = 0;
    for (std::uint8_t p : planned) most = std::max<int>(most, p);
    std::printf("workload: %lld blocks, %lld programs (%lld completed, %lld aborted, %lld disabled, %lld faults), "
                "%lld overrides, %lld holds; up to %d blocks planned in one tick\n",
                static_cast<long long>(stats.blocks), static_cast<long long>(stats.programs),
                static_cast<long long>(stats.completed), static_cast<long long>(stats.aborted),
                static_cast<long long>(stats.disabled), static_cast<long long>(stats.faulted),
                static_cast<long long>(stats.overrides), static_cast<long long>(stats.holds), most);
    return 0;
}
