// Long run of the component's servo-thread logic (ComponentLogic::update: planning on acceptance,
// FIR chain, sequence checks) over random programs with overrides, holds, aborts, disabling and
// stream faults (tests/realtime/random_operation.hpp), alternating two machines (built-in with
// axis limits; the paper's filters without limits) every `--segment` ticks.
//
//   build/bin/firtp_soak [--ticks 1e8] [--seed S] [--segment 1e7] [--report 1e7] [--budget-us 250]
//
// Checked all along: finite output, |v| and |a| within the axis limits at every sample, every
// completed program ends on its last target within 1e-9 mm with every block accepted once
// (repeats refused, nothing skipped), every fault ends its program with its error. Memory: the
// resident set (/proc/self/statm) is sampled at each report; after the first report it must not
// grow by more than 1 MiB. Exit 0 when everything held, 1 otherwise. Each report also gives the
// slowest update since the one before and how many took over 1 ms (wall clock): planning-time
// regressions show there (docs/HARDENING.md, Soak).
//
// As firtp.so runs, a period plans one block, then more while --budget-us lasts (the module's
// default, on the wall clock): how many blocks a period takes then depends on this machine's
// speed, and so do the figures. --budget-us 0 plans up to max_blocks a period whatever they cost:
// the same run for a seed on any machine (to reproduce a failure).
#include "bench_stats.hpp"
#include "random_operation.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

using namespace firtp;

namespace {

long rss_kib() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

struct Machine {
    ComponentSettings settings;
    std::unique_ptr<ComponentLogic> core;
    test::StreamRing ring;
    std::unique_ptr<test::RandomOperation> op;
    ComponentOutputs out;
    Machine(bool limits, std::uint64_t seed, std::int64_t budget_ns) : settings(test::operation_settings(limits)) {
        settings.plan_budget_ns = budget_ns;
        settings.clock_ns = bench::wall_ns;
        core = std::make_unique<ComponentLogic>(settings);
        op = std::make_unique<test::RandomOperation>(settings, seed);
    }
    // The slowest update since the last report (the servo thread's work: planning on acceptance,
    // replanning for overrides and holds), on the wall clock, which a shared machine's preemption
    // also lengthens (this thread's CPU clock is a system call: it doubled the soak's time). A
    // figure to watch, not a bound.
    std::int64_t worst_ns = 0, slow = 0;  // slow: updates over 1 ms
    bool run(std::int64_t ticks) {
        for (std::int64_t k = 0; k < ticks; ++k) {
            op->before_tick(ring);
            const std::int64_t t0 = bench::wall_ns();
            core->update(op->inputs(), ring.source(), out);
            const std::int64_t ns = bench::wall_ns() - t0;
            worst_ns = std::max(worst_ns, ns);
            slow += ns > 1000000;
            op->after_tick(out, ring);
        }
        return op->ok();
    }
};

void add(test::OperationStats& total, const test::OperationStats& s) {
    total.ticks += s.ticks;
    total.blocks += s.blocks;
    total.programs += s.programs;
    total.completed += s.completed;
    total.aborted += s.aborted;
    total.disabled += s.disabled;
    total.braked += s.braked;
    total.faulted += s.faulted;
    total.repeats += s.repeats;
    total.overrides += s.overrides;
    total.holds += s.holds;
    total.violations += s.violations;
    total.worst_end_error = std::max(total.worst_end_error, s.worst_end_error);
    total.worst_limit_ratio = std::max(total.worst_limit_ratio, s.worst_limit_ratio);
}

}  // namespace

int main(int argc, char** argv) {
    double ticks = 1e8, segment = 1e7, report = 1e7;
    std::uint64_t seed = 1;
    double budget_us = defaults::plan_budget_us;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] { return i + 1 < argc ? std::stod(argv[++i]) : 0.0; };
        if (a == "--ticks") ticks = value();
        else if (a == "--segment") segment = value();
        else if (a == "--report") report = value();
        else if (a == "--seed") seed = static_cast<std::uint64_t>(value());
        else if (a == "--budget-us") budget_us = value();
        else {
            std::fprintf(stderr, "usage: firtp_soak [--ticks 1e8] [--seed S] [--segment 1e7] [--report 1e7] [--budget-us %d]\n",
                         defaults::plan_budget_us);
            return a == "--help" ? 0 : 2;
        }
    }
    segment = std::max(1.0, std::min(segment, report));
    const auto budget_ns = static_cast<std::int64_t>(budget_us * 1e3);
    Machine machines[2] = {Machine(true, seed * 2 + 1, budget_ns), Machine(false, seed * 2 + 2, budget_ns)};
    const auto begin = std::chrono::steady_clock::now();
    std::printf("firtp_soak: %.3g ticks (%.1f h of motion at 1 kHz), seed %llu, machines alternate every %.3g ticks, "
                "planning budget %.0f us%s\n",
                ticks, ticks / 3.6e6, static_cast<unsigned long long>(seed), segment, budget_us,
                budget_ns > 0 ? " (wall clock: runs differ)" : " (none: reproducible)");
    std::printf("%12s %9s %9s %8s %7s %7s %7s %7s %10s %10s %9s %9s %9s %6s\n", "ticks", "blocks", "completed", "aborted",
                "disabl", "braked", "faults", "repeats", "end err mm", "|v|,|a|/lim", "RSS KiB", "ticks/s", "worst us",
                ">1 ms");
    long rss_first = -1, rss_max = 0;
    std::int64_t done = 0, next_report = static_cast<std::int64_t>(report);
    bool ok = true;
    int which = 0;
    while (done < static_cast<std::int64_t>(ticks) && ok) {
        const std::int64_t n = std::min(static_cast<std::int64_t>(segment), static_cast<std::int64_t>(ticks) - done);
        ok = machines[which].run(n);
        which = 1 - which;
        done += n;
        if (done >= next_report || done >= static_cast<std::int64_t>(ticks) || !ok) {
            next_report += static_cast<std::int64_t>(report);
            test::OperationStats total;
            for (const Machine& m : machines) add(total, m.op->stats());
            const long rss = rss_kib();
            if (rss_first < 0) rss_first = rss;
            rss_max = std::max(rss_max, rss);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            std::int64_t worst_ns = 0, slow = 0;
            for (Machine& m : machines) {  // since the last report
                worst_ns = std::max(worst_ns, m.worst_ns);
                slow += m.slow;
                m.worst_ns = m.slow = 0;
            }
            std::printf("%12lld %9lld %9lld %8lld %7lld %7lld %7lld %7lld %10.2g %10.6f %9ld %9.3g %9.0f %6lld\n",
                        static_cast<long long>(done), static_cast<long long>(total.blocks),
                        static_cast<long long>(total.completed), static_cast<long long>(total.aborted),
                        static_cast<long long>(total.disabled), static_cast<long long>(total.braked),
                        static_cast<long long>(total.faulted), static_cast<long long>(total.repeats),
                        total.worst_end_error, total.worst_limit_ratio, rss, static_cast<double>(done) / seconds,
                        1e-3 * static_cast<double>(worst_ns), static_cast<long long>(slow));
            std::fflush(stdout);
        }
    }
    for (const Machine& m : machines)
        if (!m.op->ok()) std::printf("FAILED: %s\n", m.op->stats().first_violation);
    const long growth = rss_max - rss_first;
    const bool flat = growth <= 1024;
    std::printf("memory: RSS %ld KiB at the first report, at most %ld KiB later (%+ld KiB): %s\n", rss_first, rss_max,
                growth, flat ? "flat" : "GROWING");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::printf("%s: %lld ticks in %.0f s\n", ok && flat ? "PASSED" : "FAILED", static_cast<long long>(done), seconds);
    return ok && flat ? 0 : 1;
}
