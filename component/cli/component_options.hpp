// Command lines of the commands that run the component: run, serve, host.
#pragma once

#include "plan_options.hpp"

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace firtp::cli {

struct ComponentOptions {
    PlanOptions plan;                              // program (run, host), machine, outputs (run)
    std::string lcm_url;                           // --lcm-url ("": the command's default)
    std::optional<std::filesystem::path> module;   // --module firtp.so
    std::optional<std::filesystem::path> lcm_log;  // run --lcm-log: every message of the run
    bool exit_when_done = false;                   // serve --exit-when-done
    double duration = 0.0;                         // serve --duration S (0: until interrupted)
    int rt_priority = 80;                          // serve --rt-prio N: SCHED_FIFO N where allowed (0: normal)
    int queue = defaults::queue;                   // serve --queue N: blocks the component holds (InProcessSettings)
    double max_feed = 1.5;                         // host --max-feed
};

ComponentOptions parse_run_options(std::span<const std::string> args);
ComponentOptions parse_serve_options(std::span<const std::string> args);
ComponentOptions parse_host_options(std::span<const std::string> args);
std::string run_help();
std::string serve_help();
std::string host_help();

}  // namespace firtp::cli
