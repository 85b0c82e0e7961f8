#include "component_options.hpp"
#include "plan_run.hpp"
#include "record_config.hpp"
#include "run_command.hpp"
#include <firtp/in_process_component.hpp>

#include <firtp/hal_shim/runtime.hpp>
#include <firtp/messages.hpp>

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>

namespace firtp::cli {
namespace {

std::atomic<bool> stop_requested{false};

extern "C" void request_stop(int) { stop_requested = true; }

// Whether a thread of this process may run SCHED_FIFO at `priority`: "" or why not.
std::string fifo_refused(int priority) {
    int rc = 0;
    std::thread probe([&] {
        sched_param sp{};
        sp.sched_priority = priority;
        rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp);
    });
    probe.join();
    return rc == 0 ? "" : std::strerror(rc);
}

}  // namespace

int serve_command(std::span<const std::string> args) {
    const ComponentOptions options = parse_serve_options(args);
    if (options.plan.help) {
        std::cout << serve_help();
        return 0;
    }
    const MachineConfig machine = load_machine_config(options.plan);
    const std::string url = options.lcm_url.empty() ? messages::default_url() : options.lcm_url;
    const auto lcm = messages::open(url);
    const InProcessSettings settings = serve_component_settings(machine, options.queue);
    firtp::InProcessComponent chain(*lcm, machine, options.module.value_or(firtp::default_module_path()), settings);
    ConfigPublisher config(*lcm, config_message("serve", args, options, machine, settings));  // for recorders
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    // Real time where the system allows it (root, CAP_SYS_NICE or an rtprio limit), and say which.
    std::string scheduling = "SCHED_OTHER (normal scheduling, --rt-prio 0)";
    if (options.rt_priority > 0) {
        if (const std::string why = fifo_refused(options.rt_priority); why.empty()) {
            hal_shim::set_rt_priority(options.rt_priority);
            scheduling = "SCHED_FIFO " + std::to_string(options.rt_priority);
        } else {
            scheduling = "SCHED_OTHER (SCHED_FIFO " + std::to_string(options.rt_priority) + " refused: " + why + ")";
        }
    }
    chain.start();
    std::cout << "firtp serve: servo thread every " << machine.period * 1e3 << " ms, " << scheduling
              << ", waiting for blocks on " << url << std::endl;

    using Clock = std::chrono::steady_clock;
    const Clock::time_point begin = Clock::now();
    Clock::time_point idle_since = begin;
    while (!stop_requested) {
        lcm->handleTimeout(1);
        chain.poll();
        config.poll();
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
