#include "plan_sink.hpp"

namespace firtp::cli {

PlanSink::PlanSink(PlanRun& run, std::ostream* csv, ProgressLine* progress, bool keep_samples)
    : run_(run), progress_(progress), keep_(keep_samples) {
    if (csv) csv_.emplace(*csv);
    auto on_corner = [this](std::size_t i, double e) { corner_measured(i, e); };
    if (run.points.spooled()) {
        points_ = run.points.read();
        measure_.emplace(*points_, run.parameters.period, on_corner);
    } else {
        measure_.emplace(run.points.kept(), run.parameters.period, on_corner);
    }
}

void PlanSink::sample(const AxisState& state) {
    if (csv_) csv_->row(state);
    if (keep_) run_.trajectory.samples.push_back(state);
    plot_.add(state);
    measure_->add(state);
    if (progress_) progress_->update(measure_->segment(), state.time);
}

void PlanSink::corner(const CornerReport& report) {
    run_.trajectory.corners.push_back(report);
    const std::size_t index = run_.trajectory.corners.size() - 1;
    for (auto p = pending_.begin(); p != pending_.end();)
        if (p->first == index) {
            plot_.corner_error(p->first, p->second, report);
            p = pending_.erase(p);
        } else {
            ++p;
        }
}

void PlanSink::corner_measured(std::size_t index, double error) {
    if (index < run_.trajectory.corners.size()) plot_.corner_error(index, error, run_.trajectory.corners[index]);
    else pending_.emplace_back(index, error);
}

void PlanSink::finish() {
    take_measurement(run_, measure_->finish());
    if (run_.measured.corner_errors.size() != run_.trajectory.corners.size()) plot_.zooms.clear();  // unpaired
}

PlotSamples plot_samples_of(const PlanRun& run) {
    PlotSamples plot;
    // The zooms first, so that they look at every sample.
    for (std::size_t i = 0; i < run.trajectory.corners.size(); ++i)
        if (run.corner_errors[i]) plot.corner_error(i, *run.corner_errors[i], run.trajectory.corners[i]);
    for (const AxisState& s : run.trajectory.samples) plot.add(s);
    return plot;
}

}  // namespace firtp::cli
