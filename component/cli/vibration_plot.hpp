// gnuplot scripts (data inline, pngcairo) for the vibration figures: the modes' time responses
// under each planner, and acceleration spectra with the chain's magnitude (Eq. 9) and the modes
// marked.
#pragma once

#include "vibration_study.hpp"

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace firtp::cli {

// One panel per plant mode: its deflection against time under each planner.
std::string response_plot_script(const VibrationStudy& study, const std::filesystem::path& png);

struct SpectrumPlot {
    std::string title;
    std::vector<int> axes;  // one panel per axis
    struct Series {
        std::string label;
        const std::vector<AxisState>* samples = nullptr;
    };
    std::vector<Series> series;  // the same axes' acceleration, several planners
    struct Chain {
        std::string label;
        FilterTimes filters;
    };
    std::vector<Chain> chains;  // |M(j 2 pi f)| in a last panel
    struct Mark {
        std::string label;
        double frequency_hz = 0.0;
    };
    std::vector<Mark> marks;  // vertical lines: the modes
    double max_hz = 30.0;
};

// Panels: |DFT| of each axis's acceleration per series (log scale), then the chains' magnitude.
std::string spectrum_plot_script(const SpectrumPlot& plot, const std::filesystem::path& png);

// "tuned: T = 147.1, 87.7 ms", a chain's key entry.
std::string chain_label(const std::string& name, const FilterTimes& filters);

// The spectrum figure of a study: each plant axis under the three planners, the tuned and untuned
// chains, the plant modes marked.
SpectrumPlot study_spectrum(const VibrationStudy& study);

// A frequency range that shows the marks and the chains' first zeros: max(30, 2.5 x the highest
// mark, 1.5 / the shortest stage), at most 500 Hz.
double spectrum_range(const std::vector<SpectrumPlot::Mark>& marks, const std::vector<SpectrumPlot::Chain>& chains);

}  // namespace firtp::cli
