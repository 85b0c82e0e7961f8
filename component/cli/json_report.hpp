// The JSON report of `firtp plan --json`.
#pragma once

#include "plan_run.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace firtp::cli {

// Keys: program, machine, blocks (that move), cycle_time_s, closed_form_cycle_time_s, corners[], measured{}.
nlohmann::json json_report(const PlanRun& run, const std::string& program_name);

}  // namespace firtp::cli
