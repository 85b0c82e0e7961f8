#include "plan_outputs.hpp"

#include "csv_writer.hpp"
#include "json_report.hpp"
#include "output_files.hpp"
#include "plot.hpp"

namespace firtp::cli {

std::vector<std::filesystem::path> write_outputs(const PlanRun& run, const PlanOptions& options,
                                                 const std::optional<std::filesystem::path>& gnuplot) {
    OutputFiles outputs;
    std::vector<std::filesystem::path> written;
    if (options.csv) {
        outputs.write(*options.csv, [&](std::ostream& out) { write_csv(out, run.trajectory.samples); });
        written.push_back(*options.csv);
    }
    if (options.json) {
        outputs.write(*options.json,
                      [&](std::ostream& out) { out << json_report(run, options.program.string()).dump(2) << "\n"; });
        written.push_back(*options.json);
    }
    if (options.plot) {
        write_plot(run, options.program.filename().string(), *gnuplot, outputs.create(*options.plot));
        written.push_back(*options.plot);
    }
    outputs.commit();
    return written;
}

}  // namespace firtp::cli
