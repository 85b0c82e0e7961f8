#include "plan_command.hpp"

#include "csv_writer.hpp"
#include "gnuplot_pipe.hpp"
#include "json_report.hpp"
#include "output_files.hpp"
#include "plan_options.hpp"
#include "plan_run.hpp"
#include "plot.hpp"
#include "summary.hpp"

#include <fstream>
#include <iostream>
#include <optional>
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

int plan_command(std::span<const std::string> args) {
    const PlanOptions options = parse_plan_options(args);
    if (options.help) {
        std::cout << plan_help();
        return 0;
    }
    // Before the planning work: a missing gnuplot fails at once.
    const std::optional<std::filesystem::path> gnuplot =
        options.plot ? std::optional(find_gnuplot()) : std::nullopt;

    const PlanRun run = run_plan(options);
    const std::string name = options.program.filename().string();

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
        write_plot(run, name, *gnuplot, outputs.create(*options.plot));
        written.push_back(*options.plot);
    }
    outputs.commit();
    print_summary(std::cout, run, name, written);
    return 0;
}

}  // namespace firtp::cli
