// The figures of a VibrationStudy as text (firtp simulate), Markdown (files, reports) and JSON.
#pragma once

#include "vibration_study.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace firtp::cli {

// Filters, then per plant mode and planner: cycle time, stops, residual vibration after stops
// (largest), oscillation while moving (largest), lag while moving (largest), with shares of the
// untuned firtp's; then the tuned chain's robust bands and the delay cost.
void print_vibration(std::ostream& out, const VibrationStudy& study);

// The same as Markdown tables (a heading level `level`, e.g. "##").
std::string vibration_markdown(const VibrationStudy& study, const std::string& level);

// Every figure, and every stop's residual, for scripts and tests.
nlohmann::json vibration_json(const VibrationStudy& study);

// "-5.5 % ... +6.8 %", "-20.0 % ... beyond +100 %", or "none".
std::string band_text(const FrequencyBand& band);

}  // namespace firtp::cli
