// The --csv / --json / --plot outputs of a planned (or run) program, all or nothing: the CSV is
// filled while the samples are made, JSON and plot once they are all measured.
#pragma once

#include "output_files.hpp"
#include "plan_options.hpp"
#include "plan_run.hpp"
#include "plot_samples.hpp"

#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

namespace firtp::cli {

class PlanOutputs {
public:
    explicit PlanOutputs(const PlanOptions& options);

    // Where the CSV rows go while planning; null without --csv.
    std::ostream* csv() { return csv_ ? &*csv_ : nullptr; }

    // Writes JSON and plot, then puts every file in place; returns the files written. Throws (and
    // leaves none behind) when any fails; so does destroying the object before this.
    std::vector<std::filesystem::path> finish(const PlanRun& run, const PlotSamples& plot,
                                              const std::optional<std::filesystem::path>& gnuplot);

private:
    const PlanOptions& options_;
    OutputFiles files_;
    std::optional<std::ofstream> csv_;
};

}  // namespace firtp::cli
