// Sustained block rate host -> component over LCM (udpm on loopback by default), and the cost of
// the servo-thread function while the stream and the bridge run. Prints figures; run it with
// tests/bench/stream_bench.sh (a private network namespace with a multicast route).
//
//   firtp_stream_bench [--blocks N] [--url URL] [--max-blocks K]
#include <firtp/host.hpp>
#include <firtp/machine.hpp>
#include <firtp/messages.hpp>
#include <firtp/servo_chain.hpp>

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
    MachineConfig machine = default_machine();
    machine.given_times = {0.02, 0.005};

    // Component side: its own LCM endpoint, the servo thread on the real-time clock.
    auto component_lcm = messages::open(url);
    ChainSettings settings;
    settings.queue = blocks + 16;  // the stream is measured, not how fast the machine cuts
    settings.max_blocks = max_blocks;
    settings.plan_budget_us = 400;  // as firtp serve: 40 % of the period
    ServoChain chain(*component_lcm, machine, default_module_path(), settings);
    chain.start();

    std::atomic<bool> done{false};
    std::vector<long> update_ns;
    std::thread component([&] {
        while (!done) {
            component_lcm->handleTimeout(1);
            chain.poll();
            if (const long ns = chain.update_time_ns(); ns > 0) update_ns.push_back(ns);
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
    done = true;
    component.join();

    std::sort(update_ns.begin(), update_ns.end());
    const auto quantile = [&](double q) {
        if (update_ns.empty()) return 0.0;
        const auto i = static_cast<std::size_t>(q * static_cast<double>(update_ns.size() - 1));
        return static_cast<double>(update_ns[i]) / 1e3;
    };
    double mean = 0.0;
    for (long ns : update_ns) mean += static_cast<double>(ns) / 1e3;
    mean = update_ns.empty() ? 0.0 : mean / static_cast<double>(update_ns.size());

    std::printf("stream: %zu of %d blocks accepted in %.3f s = %.0f blocks/s over %s\n", acknowledged, blocks, seconds,
                static_cast<double>(acknowledged) / seconds, url.c_str());
    std::printf("        published %lld (resends %lld), refused %lld, status messages %lld\n",
                static_cast<long long>(stats.blocks_published), static_cast<long long>(stats.go_backs),
                static_cast<long long>(stats.rejected), static_cast<long long>(stats.statuses));
    std::printf("firtp.update while streaming (up to %d blocks, 400 us planning, per 1 ms period): mean %.1f us, median %.1f us, "
                "p99 %.1f us, max %.1f us over %zu samples\n",
                max_blocks, mean, quantile(0.5), quantile(0.99), quantile(1.0), update_ns.size());
    return acknowledged == static_cast<std::size_t>(blocks) ? 0 : 1;
}
