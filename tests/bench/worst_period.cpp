// The planning a servo period does on a dense path, without this machine's noise. The chords of
// examples/polygon360.ngc round and round (chord_moves.hpp), on compare.py's machine as firtp_tp
// plans it (every axis 300 mm/s, 5000 mm/s^2, --jerk; 1 ms period, highest override 100 %, 4,096
// blocks). --per-period blocks are added before each period (not timed: past the window's reach
// an add only queues the block); Planner::update is timed, whose commit joins the waiting blocks
// to the window in batches (lookahead_reach.cpp). --with-adds times the adds too, as part of their
// period: with --per-period 1 that is LinuxCNC feeding firtp_tp one block a servo period, a window
// that may never reach that far (the path used about as fast as it comes). Planning is
// deterministic, so period k does the same work in every run; each period's least thread-CPU time
// over --repeat runs is its own cost.
// Prints their p99, p999 and max, how many exceed 50 us (issue 13's worst), and the sum.
//
//   firtp_worst_period [--jerk 1e5] [--feed 250] [--laps 6] [--repeat 5] [--per-period 8] [--with-adds]
//
// Exit status 1 unless the motion ends exactly on the last chord.
#include "bench_stats.hpp"
#include "chord_moves.hpp"

#include <firtp/planner.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace firtp;

int main(int argc, char** argv) {
    double jerk = 1e5, feed = 250.0;
    int laps = 6, repeat = 5, per_period = 8;
    bool with_adds = false;
    for (int i = 1; i < argc; ++i) {
        const bool has_value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--jerk") && has_value) jerk = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--feed") && has_value) feed = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--laps") && has_value) laps = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--repeat") && has_value) repeat = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--per-period") && has_value) per_period = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--with-adds")) with_adds = true;
        else {
            std::fprintf(stderr, "usage: %s [--jerk 1e5] [--feed 250] [--laps 6] [--repeat 5] [--per-period 8] [--with-adds]\n", argv[0]);
            return 2;
        }
    }
    if (!(jerk > 0.0) || !(feed > 0.0) || laps < 1 || repeat < 1 || per_period < 1) {
        std::fprintf(stderr, "firtp_worst_period: --jerk, --feed > 0; --laps, --repeat, --per-period >= 1\n");
        return 2;
    }
    PlannerParameters parameters;
    parameters.queue_capacity = 4096;
    parameters.max_rate = 1.0;
    parameters.limits.axes = 3;
    for (int a = 0; a < 3; ++a) parameters.limits.axis[a] = {300.0, 5000.0, jerk};
    const std::int64_t chords = 360LL * laps;

    std::vector<double> least;  // us, per period
    std::vector<bool> moving;   // the tool moved in the period before
    std::uint64_t checks = 0;
    for (int run = 0; run < repeat; ++run) {
        Planner planner(parameters, AxisVector::Zero());
        bench::Chords moves(feed);
        Block last;
        PlannerInput in;
        PlannerOutput out;
        for (std::size_t k = 0;; ++k) {
            if (moving.size() <= k) moving.push_back(out.state.velocity != AxisVector::Zero());
            const std::int64_t a0 = bench::thread_cpu_ns();
            for (int n = 0; n < per_period && moves.count() < chords && planner.free() > 0; ++n) {
                last = moves.next();
                if (planner.add(last) != Result::ok) {
                    std::fprintf(stderr, "firtp_worst_period: chord %lld not planned\n", static_cast<long long>(last.line));
                    return 1;
                }
            }
            in.end_of_program = moves.count() == chords;
            const std::int64_t c0 = bench::thread_cpu_ns();
            const Result result = planner.update(in, out);
            const double us = static_cast<double>(bench::thread_cpu_ns() - (with_adds ? a0 : c0)) * 1e-3;
            if (least.size() <= k) least.push_back(us);
            else least[k] = std::min(least[k], us);
            if (result == Result::finished && in.end_of_program) break;
        }
        if (out.state.position != last.target) {
            std::fprintf(stderr, "firtp_worst_period: the motion ended off the last chord\n");
            return 1;
        }
        checks = planner.stats().checks;
    }
    std::vector<double> sorted = least;
    std::sort(sorted.begin(), sorted.end());
    double sum = 0.0;
    long over = 0;
    long over_moving = 0;
    for (std::size_t k = 0; k < least.size(); ++k) sum += least[k], over += least[k] > 50.0, over_moving += least[k] > 50.0 && moving[k];
    std::printf("%lld chords of 0.35 mm at %g mm/s, jerk %g mm/s^3, %d added a period%s: %zu periods, %llu checks\n",
                static_cast<long long>(chords), feed, jerk, per_period, with_adds ? " (timed)" : "", least.size(),
                static_cast<unsigned long long>(checks));
    std::printf("  a period's planning, least of %d runs (thread CPU): p99 %.1f  p999 %.1f  max %.1f us; over 50 us: %ld (%ld under way); sum %.1f ms\n",
                repeat, sorted[sorted.size() * 99 / 100], sorted[sorted.size() * 999 / 1000], sorted.back(), over, over_moving, sum * 1e-3);
    return 0;
}
