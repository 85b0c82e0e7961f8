// Command line of `firtp plan`.
#pragma once

#include <firtp/machine.hpp>
#include <firtp/parameters.hpp>

#include <boost/program_options.hpp>

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
    std::optional<std::string> modes, robust;      // --modes --robust (override [FIRTP]MODES, ROBUST)
    std::optional<std::filesystem::path> report;   // --report DIR
    bool help = false;
};

// Arguments after "plan". Throws UsageError for unknown flags, bad values or a missing program.
PlanOptions parse_plan_options(std::span<const std::string> args);

// Flag groups shared by the commands (plan, run, serve, host).
boost::program_options::options_description machine_flags();  // --ini --t1 --t2 --tolerance --period ...
boost::program_options::options_description output_flags();   // --csv --json --plot
boost::program_options::options_description mode_flags();     // --modes --robust
// Parses args with `flags` (plus the PROGRAM positional when takes_program); UsageError names `command`.
boost::program_options::variables_map parse_flags(std::span<const std::string> args,
                                                  const boost::program_options::options_description& flags,
                                                  const std::string& command, bool takes_program);
void read_machine_flags(const boost::program_options::variables_map& vm, PlanOptions& options);
void read_output_flags(const boost::program_options::variables_map& vm, PlanOptions& options);
void read_mode_flags(const boost::program_options::variables_map& vm, PlanOptions& options);

// Text of `firtp plan --help`.
std::string plan_help();

}  // namespace firtp::cli
