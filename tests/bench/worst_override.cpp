// A servo period that changes the feed override: its cost against the blocks waiting.
//
//   firtp_worst_override [--depth 256] [--ticks 200000] [--every 20] [--seed 1] [--chords] [--json]
//
// Machine and moves as firtp_worst_tick (every axis 300 mm/s, 5000 mm/s^2, 1e5 mm/s^3, highest
// override 150 %), the queue kept `--depth` blocks deep. --chords: a dense path instead, round and
// round a circle of R20 in 0.35 mm chords at 300 mm/s, G64 P0.5 (examples/polygon360.ngc's),
// where the motion's stop spans the most blocks. Every `--every` periods the operator
// turns the override: half the time a knob's step (+-5 %), else a jump anywhere in 10-150 %.
// Each update() is timed with this thread's CPU clock; the periods with a change and those
// without are reported apart, with how many took over 1 ms (the servo period), and each add()
// (the blocks that refill the queue come between periods) likewise. At the end the
// queue drains and the output must rest exactly on the last command; exit status 1 otherwise.
#include "bench_stats.hpp"
#include "chord_moves.hpp"
#include "random_moves.hpp"

#include <firtp/planner.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

using namespace firtp;
using namespace firtp::bench;

namespace {

struct Periods {
    Histogram cpu{1000, 20'000'000};
    std::int64_t over_ms = 0;
    void add(std::int64_t ns) {
        cpu.add(ns);
        over_ms += ns > 1'000'000;
    }
    void print(const char* name) {
        std::printf("  %-16s %8llu periods: mean %7.1f us, p50 %6.0f, p99 %6.0f, max %6.0f us, over 1 ms %lld\n", name,
                    static_cast<unsigned long long>(cpu.count()), cpu.mean() * 1e-3,
                    static_cast<double>(cpu.quantile(0.5)) * 1e-3, static_cast<double>(cpu.quantile(0.99)) * 1e-3,
                    static_cast<double>(cpu.max()) * 1e-3, static_cast<long long>(over_ms));
    }
    std::string json() {
        return "{\"cpu_ns\":" + cpu.json() + ",\"over_1ms\":" + std::to_string(over_ms) + "}";
    }
};

}  // namespace

int main(int argc, char** argv) {
    long long ticks = 200'000, depth = 256, every = 20;
    std::uint64_t seed = 1;
    bool json = false, chords = false;
    for (int i = 1; i < argc; ++i) {
        const bool has_value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--json")) json = true;
        else if (!std::strcmp(argv[i], "--chords")) chords = true;
        else if (!std::strcmp(argv[i], "--ticks") && has_value) ticks = std::atoll(argv[++i]);
        else if (!std::strcmp(argv[i], "--depth") && has_value) depth = std::atoll(argv[++i]);
        else if (!std::strcmp(argv[i], "--every") && has_value) every = std::atoll(argv[++i]);
        else if (!std::strcmp(argv[i], "--seed") && has_value) seed = std::strtoull(argv[++i], nullptr, 10);
        else {
            std::fprintf(stderr, "usage: %s [--depth N] [--ticks N] [--every N] [--seed S] [--chords] [--json]\n", argv[0]);
            return 2;
        }
    }
    if (ticks < 1 || depth < 2 || every < 1) {
        std::fprintf(stderr, "ticks >= 1, depth >= 2, every >= 1\n");
        return 2;
    }

    PlannerParameters parameters;
    parameters.queue_capacity = static_cast<std::size_t>(depth);
    parameters.max_rate = 1.5;
    parameters.limits.axes = 3;
    for (int a = 0; a < 3; ++a) parameters.limits.axis[a] = {300.0, 5000.0, 1e5};
    Planner planner(parameters, AxisVector::Zero());
    RandomMoves random_moves(3, seed);
    Chords chord_moves;
    const auto next_move = [&] { return chords ? chord_moves.next() : random_moves.next(); };
    const auto moves_count = [&] { return chords ? chord_moves.count() : random_moves.count(); };
    std::mt19937_64 knob(seed + 1000);
    std::uniform_real_distribution<double> unit(0.0, 1.0);

    Periods changed, steady, adds;
    PlannerInput in;
    PlannerOutput out;
    AxisVector last_target = AxisVector::Zero();
    std::int64_t changes = 0;
    for (long long k = 0; k < ticks; ++k) {
        while (planner.free() > 0) {  // (between periods, each add timed apart)
            const Block b = next_move();
            const std::int64_t a0 = thread_cpu_ns();
            const Result added = planner.add(b);
            adds.add(thread_cpu_ns() - a0);
            if (refused(added)) {
                std::fprintf(stderr, "block %lld refused\n", static_cast<long long>(b.line));
                return 1;
            }
            last_target = b.target;
        }
        const bool change = k % every == every - 1;
        if (change) {
            const double r = unit(knob) < 0.5 ? in.rate + (unit(knob) < 0.5 ? -0.05 : 0.05) : 0.1 + 1.4 * unit(knob);
            in.rate = std::clamp(r, 0.1, 1.5);
            ++changes;
        }
        const std::int64_t c0 = thread_cpu_ns();
        planner.update(in, out);
        const std::int64_t ns = thread_cpu_ns() - c0;
        (change ? changed : steady).add(ns);
    }
    in.end_of_program = true;
    while (planner.update(in, out) == Result::working) {
    }
    const long long end_period = static_cast<long long>(planner.ticks());
    const bool exact = out.state.position == last_target && out.state.velocity == AxisVector::Zero();
    const std::uint64_t checks = planner.stats().checks;

    if (json) {
        std::printf("{\"depth\":%lld,\"ticks\":%lld,\"changes\":%lld,\"blocks\":%lld,\"checks\":%llu,\"end_exact\":%s,"
                    "\"end_period\":%lld,\"changed\":%s,\"steady\":%s,\"adds\":%s}\n",
                    depth, ticks, static_cast<long long>(changes), static_cast<long long>(moves_count()),
                    static_cast<unsigned long long>(checks), exact ? "true" : "false", end_period, changed.json().c_str(),
                    steady.json().c_str(), adds.json().c_str());
    } else {
        std::printf("depth %lld: %lld periods, %lld override changes, %lld blocks, %llu checks\n", depth, ticks,
                    static_cast<long long>(changes), static_cast<long long>(moves_count()),
                    static_cast<unsigned long long>(checks));
        changed.print("with a change");
        steady.print("without");
        adds.print("adds");
        std::printf("  end: %s, at rest from period %lld\n", exact ? "exactly on the last command" : "NOT on the last command",
                    end_period);
    }
    return exact ? 0 : 1;
}
