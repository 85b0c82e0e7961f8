// The JSON report of `firtp plan --json`.
#pragma once

#include "plan_run.hpp"

#include <nlohmann/json.hpp>

#include <ostream>

#include <string>

namespace firtp::cli {

// Keys: program, machine, blocks (that move), cycle_time_s, closed_form_cycle_time_s, corners[], measured{}.
// with_corners false: corners is [].
nlohmann::json json_report(const PlanRun& run, const std::string& program_name, bool with_corners = true);

// json_report(...).dump(2) and a newline, byte for byte, written one corner at a time (a long
// program's corners never sit in memory as one JSON document).
void write_json_report(std::ostream& out, const PlanRun& run, const std::string& program_name);

}  // namespace firtp::cli
