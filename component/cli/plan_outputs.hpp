// Writes the --csv / --json / --plot outputs of a planned (or run) program, all or nothing.
#pragma once

#include "plan_options.hpp"
#include "plan_run.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace firtp::cli {

// Returns the files written; throws (and leaves none behind) when any fails.
std::vector<std::filesystem::path> write_outputs(const PlanRun& run, const PlanOptions& options,
                                                 const std::optional<std::filesystem::path>& gnuplot);

}  // namespace firtp::cli
