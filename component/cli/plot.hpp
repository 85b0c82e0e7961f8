// The PNG of `firtp plan --plot`: XY path, corner zooms, feed and axis accelerations.
#pragma once

#include "plan_run.hpp"
#include "plot_samples.hpp"

#include <filesystem>
#include <string>

namespace firtp::cli {

// gnuplot script (data inline) that draws `run` into `png` with the pngcairo terminal.
// The samples come from `plot` (bounded: plot_samples.hpp), the program and corners from `run`.
std::string plot_script(const PlanRun& run, const PlotSamples& plot, const std::string& program_name,
                        const std::filesystem::path& png);

// Draws the plot with `gnuplot` (see find_gnuplot) into `png`.
void write_plot(const PlanRun& run, const PlotSamples& plot, const std::string& program_name,
                const std::filesystem::path& gnuplot, const std::filesystem::path& png);

}  // namespace firtp::cli
