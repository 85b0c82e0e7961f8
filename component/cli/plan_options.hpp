// Command line of `firtp plan`.
#pragma once

#include <firtp/machine.hpp>
#include <firtp/parameters.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace firtp::cli {

struct PlanOptions {
    std::filesystem::path program;                 // PROGRAM.ngc
    std::optional<std::filesystem::path> ini;      // --ini, else default_machine()
    MachineOverrides overrides;                    // --t1 --t2 --tolerance --period
    std::optional<ToleranceMeaning> tolerance_meaning;
    std::optional<std::filesystem::path> csv, json, plot;
    bool help = false;
};

// Arguments after "plan". Throws UsageError for unknown flags, bad values or a missing program.
PlanOptions parse_plan_options(std::span<const std::string> args);

// Text of `firtp plan --help`.
std::string plan_help();

}  // namespace firtp::cli
