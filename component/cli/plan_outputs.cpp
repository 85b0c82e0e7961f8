#include "plan_outputs.hpp"

#include "csv_writer.hpp"
#include "json_report.hpp"
#include "output_files.hpp"
#include "plot.hpp"

#include <fstream>
#include <stdexcept>

namespace firtp::cli {
namespace {

// Opens a temporary output, lets `write` fill it and checks that every byte reached the file.
template <class Write>
void write_text(const std::filesystem::path& temporary, const std::filesystem::path& target, Write&& write) {
    std::ofstream out(temporary, std::ios::binary);
    write(out);
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + target.string() + "'");
}

}  // namespace

std::vector<std::filesystem::path> write_outputs(const PlanRun& run, const PlanOptions& options,
                                                 const std::optional<std::filesystem::path>& gnuplot) {
    OutputFiles outputs;
    std::vector<std::filesystem::path> written;
    if (options.csv) {
        write_text(outputs.create(*options.csv), *options.csv,
                   [&](std::ostream& out) { write_csv(out, run.trajectory.samples); });
        written.push_back(*options.csv);
    }
    if (options.json) {
        write_text(outputs.create(*options.json), *options.json,
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
