// Sustained block rate host -> component over LCM (udpm on loopback by default), and the cost of
// the servo-thread function while the stream and the bridge run. Prints figures; run it with
// tests/bench/stream_bench.sh (a private network namespace with a multicast route).
//
//   firtp_stream_bench [--blocks N] [--url URL] [--max-blocks K]
#include <firtp/host.hpp>
#include <firtp/machine.hpp>
#include <firtp/messages.hpp>
#include <firtp/in_process_component.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

using namespace firtp;
using Clock = std::chrono::steady_clock;

namespace {

// A dense finishing pass: 0.5 mm zig-zag steps at 250 mm/s (each block lasts 2 ms).
Program dense_program(int blocks) {
    Program p;
    p.file = "dense";
    for (int i = 0; i < blocks; ++i) {
        Block b;
        b.target[0] = 0.5 * (i + 1);
        b.target[1] = (i % 2) ? 0.3 : 0.0;
        b.feed = 250.0;
        b.tolerance = 0.01;
        b.line = i + 1;
        p.blocks.push_back(b);
    }
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    int blocks = 50000, max_blocks = 32;
    std::string url = messages::default_url();
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--blocks")) blocks = std::atoi(argv[i + 1]);
        if (!std::strcmp(argv[i], "--url")) url = argv[i + 1];
        if (!std::strcmp(argv[i], "--max-blocks")) max_blocks = std::atoi(argv[i + 1]);
    }
    // The built-in machine: filters from its limits (T1 = v/a = 60 ms, T2 = a/j = 50 ms).
    const MachineConfig machine = default_machine();

    // Component side: its own LCM endpoint, the servo thread on the real-time clock.
    auto component_lcm = messages::open(url);
    InProcessSettings settings;
    settings.queue = blocks + 16;  // the stream is measured, not how fast the machine cuts
    settings.max_blocks = max_blocks;
    settings.plan_budget_us = 500;  // as firtp serve: half the period
    InProcessComponent chain(*component_lcm, machine, default_module_path(), settings);
    chain.start();

    std::atomic<bool> done{false};
    std::atomic<bool> accepted_all{false};
    std::vector<long> update_ns, moving_ns;  // while blocks stream in; then only moving
    std::thread component([&] {
        while (!done) {
            component_lcm->handleTimeout(1);
            chain.poll();
            if (const long ns = chain.update_time_ns(); ns > 0) (accepted_all ? moving_ns : update_ns).push_back(ns);
        }
    });

    // Host side: another endpoint, as a separate process would have.
    auto host_lcm = messages::open(url);
    host::HostOptions options;
    options.max_burst = 256;
    const Program program = dense_program(blocks);
    host::Host host(*host_lcm, program, options);
    const Clock::time_point begin = Clock::now();
    while (host.progress().acknowledged < static_cast<std::size_t>(blocks) && host.result() == host::Result::running) {
        host.step();
        host_lcm->handleTimeout(1);
        if (Clock::now() - begin > std::chrono::seconds(60)) break;
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    const host::Statistics stats = host.statistics();
    const std::size_t acknowledged = host.progress().acknowledged;
    accepted_all = true;
    for (const Clock::time_point until = Clock::now() + std::chrono::seconds(2); Clock::now() < until;) {
        host.step();  // keep the host listening while the machine moves
        host_lcm->handleTimeout(1);
    }
    done = true;
    component.join();

    struct Figures { double mean, median, p99, max; };
    const auto figures = [](std::vector<long>& ns) {
        std::sort(ns.begin(), ns.end());
        const auto at = [&](double q) {
            return ns.empty() ? 0.0 : static_cast<double>(ns[static_cast<std::size_t>(q * static_cast<double>(ns.size() - 1))]) / 1e3;
        };
        double sum = 0.0;
        for (long v : ns) sum += static_cast<double>(v) / 1e3;
        return Figures{ns.empty() ? 0.0 : sum / static_cast<double>(ns.size()), at(0.5), at(0.99), at(1.0)};
    };
    const Figures streaming = figures(update_ns), moving = figures(moving_ns);

    std::printf("stream: %zu of %d blocks accepted in %.3f s = %.0f blocks/s over %s\n", acknowledged, blocks, seconds,
                static_cast<double>(acknowledged) / seconds, url.c_str());
    std::printf("        published %lld (resends %lld), refused %lld, status messages %lld\n",
                static_cast<long long>(stats.blocks_published), static_cast<long long>(stats.go_backs),
                static_cast<long long>(stats.rejected), static_cast<long long>(stats.statuses));
    std::printf("firtp.update while streaming (up to %d blocks, 500 us planning, per 1 ms period): mean %.1f us, median %.1f us, "
                "p99 %.1f us, max %.1f us over %zu samples\n",
                max_blocks, streaming.mean, streaming.median, streaming.p99, streaming.max, update_ns.size());
    std::printf("firtp.update moving, bridge publishing every period: mean %.1f us, median %.1f us, p99 %.1f us, "
                "max %.1f us over %zu samples\n",
                moving.mean, moving.median, moving.p99, moving.max, moving_ns.size());
    return acknowledged == static_cast<std::size_t>(blocks) ? 0 : 1;
}
