// Command line of `firtp simulate`.
#pragma once

#include "plan_options.hpp"

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace firtp::cli {

struct SimulateOptions {
    PlanOptions plan;                          // program, --ini, machine overrides, --modes, --robust
    double detune = 0.0;                       // --detune: the machine's modes at f (1 + detune)
    std::optional<std::filesystem::path> out;  // --out DIR
    std::optional<std::filesystem::path> json; // --json FILE: every figure as JSON (no gnuplot needed)
};

// Arguments after "simulate". Throws UsageError for unknown flags, bad values or a missing program.
SimulateOptions parse_simulate_options(std::span<const std::string> args);

// Text of `firtp simulate --help`.
std::string simulate_help();

}  // namespace firtp::cli
