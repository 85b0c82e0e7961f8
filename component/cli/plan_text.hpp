// Words for a planned program, shared by the summary, the Markdown report and the JSON report.
#pragma once

#include "plan_run.hpp"

#include <firtp/report.hpp>

#include <string>

namespace firtp::cli {

// "smoothing at the limits (jerk time ...)" or "2 FIR stages, T = ..."; the period and what the
// tolerance bounds.
std::string machine_text(const PlanRun& run);

// What bounded a junction's speed: "tolerance, X at its acceleration limit", "look-ahead", ...
std::string bound_text(const CornerReport& corner);

// The cycle time's yardstick: the paper's closed form (fixed chain) or the time at the programmed
// feed (smoothing at the limits).
std::string reference_time_text(const PlanRun& run);

// The slowest junction that is not a stop: "12.3 mm/s at line 7 (tolerance ...)", or "none".
std::string slowest_junction_text(const PlanRun& run);

}  // namespace firtp::cli
