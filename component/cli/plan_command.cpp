#include "plan_command.hpp"

#include "gnuplot_pipe.hpp"
#include "plan_checks.hpp"
#include "plan_options.hpp"
#include "plan_outputs.hpp"
#include "plan_run.hpp"
#include "plan_sink.hpp"
#include "progress_line.hpp"
#include "report.hpp"
#include "summary.hpp"

#include <iostream>
#include <optional>

namespace firtp::cli {

int plan_command(std::span<const std::string> args) {
    const PlanOptions options = parse_plan_options(args);
    if (options.help) {
        std::cout << plan_help();
        return 0;
    }
    // Before the planning work: a missing gnuplot fails at once.
    const std::optional<std::filesystem::path> gnuplot =
        options.plot || options.report ? std::optional(find_gnuplot()) : std::nullopt;
    PlanRun run = prepare_spooled_plan(options);
    PlanOutputs outputs(options);
    std::vector<std::filesystem::path> written;
    {
        ProgressLine progress("plan", run.points.size() - 1);
        PlanSink sink(run, outputs.csv(), &progress, options.report.has_value(),  // --report: keeps the samples
                      options.plot.has_value());
        plan_program(run, sink);
        sink.finish();
        progress.clear();
        written = outputs.finish(run, sink.plot(), gnuplot);
    }
    if (options.report)
        for (const auto& file : write_report(run, options, *gnuplot)) written.push_back(file);
    print_summary(std::cout, run, options.program.filename().string(), written);
    std::cout.flush();
    return report_violations(std::cerr, run);
}

}  // namespace firtp::cli
