#include "plan_outputs.hpp"

#include "json_report.hpp"
#include "plot.hpp"

#include <stdexcept>

namespace firtp::cli {

PlanOutputs::PlanOutputs(const PlanOptions& options) : options_(options) {
    if (options.csv) csv_.emplace(files_.create(*options.csv), std::ios::binary);
}

std::vector<std::filesystem::path> PlanOutputs::finish(const PlanRun& run, const PlotSamples& plot,
                                                       const std::optional<std::filesystem::path>& gnuplot) {
    std::vector<std::filesystem::path> written;
    if (csv_) {
        csv_->close();
        if (!*csv_) throw std::runtime_error("cannot write '" + options_.csv->string() + "'");
        written.push_back(*options_.csv);
    }
    if (options_.json) {
        files_.write(*options_.json, [&](std::ostream& out) { write_json_report(out, run, options_.program.string()); });
        written.push_back(*options_.json);
    }
    if (options_.plot) {
        write_plot(run, plot, options_.program.filename().string(), *gnuplot, files_.create(*options_.plot));
        written.push_back(*options_.plot);
    }
    files_.commit();
    return written;
}

}  // namespace firtp::cli
