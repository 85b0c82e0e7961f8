// Everything `firtp plan` and `firtp run` do with a sample, done as it is made: its CSV row, the
// measurement, the plot's bounded decimation, the progress line. Nothing grows with the program's
// duration unless the samples are kept on purpose (--report).
#pragma once

#include "csv_writer.hpp"
#include "plan_run.hpp"
#include "plot_samples.hpp"
#include "progress_line.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <deque>
#include <memory>
#include <optional>
#include <ostream>
#include <utility>
#include <vector>

namespace firtp::cli {

class PlanSink : public TrajectorySink {
public:
    // run: prepared (points known), no corner reports yet: they arrive through corner(), from the
    // plan that makes the samples or (run) from the reference plan made alongside the received
    // samples. csv, progress: may be null. plot: collect the plot's samples (--plot).
    PlanSink(PlanRun& run, std::ostream* csv, ProgressLine* progress, bool keep_samples, bool plot);

    void sample(const AxisState& state) override;
    void corner(const CornerReport& report) override;

    // The measurement into run (take_measurement); the plot's zooms only where every corner was paired.
    void finish();

    const PlotSamples& plot() const { return plot_; }  // empty without `plot`

private:
    void corner_measured(std::size_t index, double error);

    PlanRun& run_;
    std::optional<CsvWriter> csv_;
    ProgressLine* progress_;
    bool keep_;
    bool plot_on_;
    std::unique_ptr<PointSource> points_;  // the spool's, when spooled
    std::optional<MeasureStream> measure_;
    PlotSamples plot_;
    std::deque<CornerReport> reports_;  // reported, not yet measured
    std::deque<double> errors_;         // measured before their report came
};

// The plot's samples of a run that kept them.
PlotSamples plot_samples_of(const PlanRun& run);

}  // namespace firtp::cli
