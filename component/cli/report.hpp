// `firtp plan --report DIR`: a self-contained Markdown report of a planned program.
#pragma once

#include "plan_options.hpp"
#include "plan_run.hpp"

#include <filesystem>
#include <vector>

namespace firtp::cli {

// Writes DIR/report.md with the machine, summary, path and feed (path.png, as --plot draws it),
// axis kinematics against the limits (kinematics.png), every corner, the acceleration spectrum
// with the chain's magnitude (spectrum.png) and, when the machine has structural modes, the
// vibration tables of `firtp simulate` (response.png). DIR is created if missing; the files appear
// together or not at all. Returns the files written.
std::vector<std::filesystem::path> write_report(const PlanRun& run, const PlanOptions& options,
                                                const std::filesystem::path& gnuplot);

// Creates `dir` (and its parents); throws std::runtime_error naming it when that fails.
void make_output_directory(const std::filesystem::path& dir);

}  // namespace firtp::cli
