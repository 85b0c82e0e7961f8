#include "plan_sink.hpp"

#include <stdexcept>

namespace firtp::cli {

PlanSink::PlanSink(PlanRun& run, std::ostream* csv, ProgressLine* progress, bool keep_samples, bool plot)
    : run_(run), progress_(progress), keep_(keep_samples), plot_on_(plot) {
    if (!run.corners.empty()) throw std::logic_error("PlanSink: corner reports before the plan");
    if (csv) csv_.emplace(*csv);
    run.corners.clear_errors();
    auto on_corner = [this](std::size_t i, double e) { corner_measured(i, e); };
    if (run.points.spooled()) {
        points_ = run.points.read();
        measure_.emplace(*points_, run.parameters.period, on_corner);
    } else {
        measure_.emplace(run.points.kept(), run.parameters.period, on_corner);
    }
    measure_->forget_corner_errors();  // run.corners keeps them
}

void PlanSink::sample(const AxisState& state) {
    if (csv_) csv_->row(state);
    if (keep_) run_.trajectory.samples.push_back(state);
    if (plot_on_) plot_.add(state);
    measure_->add(state);
    if (progress_) progress_->update(measure_->segment(), state.time);
}

// Reports and errors both come in corner order: each pairs with the oldest of the other kind waiting.
void PlanSink::corner(const CornerReport& report) {
    run_.corners.push_back(report);
    const std::size_t index = run_.corners.size() - 1;
    if (errors_.empty()) return reports_.push_back(report);
    if (plot_on_) plot_.corner_error(index, errors_.front(), report);
    errors_.pop_front();
}

void PlanSink::corner_measured(std::size_t index, double error) {
    run_.corners.add_error(error);
    if (reports_.empty()) return errors_.push_back(error);
    if (plot_on_) plot_.corner_error(index, error, reports_.front());
    reports_.pop_front();
}

void PlanSink::finish() {
    take_measurement(run_, measure_->finish());
    if (!run_.corners.paired()) plot_.zooms.clear();  // unpaired
}

PlotSamples plot_samples_of(const PlanRun& run) {
    PlotSamples plot;
    // The zooms first, so that they look at every sample.
    for (std::size_t i = 0; i < run.corners.size(); ++i)
        if (run.corners.error(i)) plot.corner_error(i, *run.corners.error(i), run.corners[i]);
    for (const AxisState& s : run.trajectory.samples) plot.add(s);
    return plot;
}

}  // namespace firtp::cli
