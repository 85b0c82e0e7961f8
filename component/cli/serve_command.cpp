#include "chain_options.hpp"
#include "plan_run.hpp"
#include "run_command.hpp"
#include <firtp/servo_chain.hpp>

#include <firtp/messages.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <iostream>

namespace firtp::cli {
namespace {

std::atomic<bool> stop_requested{false};

extern "C" void request_stop(int) { stop_requested = true; }

}  // namespace

int serve_command(std::span<const std::string> args) {
    const ChainOptions options = parse_serve_options(args);
    if (options.plan.help) {
        std::cout << serve_help();
        return 0;
    }
    const MachineConfig machine = load_machine_config(options.plan);
    const std::string url = options.lcm_url.empty() ? messages::default_url() : options.lcm_url;
    const auto lcm = messages::open(url);
    ChainSettings settings;
    settings.plan_budget_us = static_cast<int>(machine.period * 1e6 * 0.5);  // half the servo period
    firtp::ServoChain chain(*lcm, machine, options.module.value_or(firtp::default_module_path()), settings);
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    chain.start();
    std::cout << "firtp serve: servo thread every " << machine.period * 1e3 << " ms, waiting for blocks on " << url
              << std::endl;

    using Clock = std::chrono::steady_clock;
    const Clock::time_point begin = Clock::now();
    Clock::time_point idle_since = begin;
    while (!stop_requested) {
        lcm->handleTimeout(1);
        chain.poll();
        const Clock::time_point now = Clock::now();
        if (options.duration > 0.0 && now - begin > std::chrono::duration<double>(options.duration)) break;
        if (!chain.bridge().idle()) idle_since = now;
        // A program has run and nothing moved for a second: the host has had its last status.
        if (options.exit_when_done && chain.bridge().blocks_forwarded() > 0 && now - idle_since > std::chrono::seconds(1))
            break;
    }
    std::cout << "firtp serve: " << chain.bridge().blocks_forwarded() << " blocks, " << chain.bridge().states_published()
              << " axis states" << std::endl;
    return 0;
}

}  // namespace firtp::cli
