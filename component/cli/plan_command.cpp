#include "plan_command.hpp"

#include "gnuplot_pipe.hpp"
#include "plan_checks.hpp"
#include "plan_options.hpp"
#include "plan_outputs.hpp"
#include "plan_run.hpp"
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
    const PlanRun run = run_plan(options);
    std::vector<std::filesystem::path> written = write_outputs(run, options, gnuplot);
    if (options.report)
        for (const auto& file : write_report(run, options, *gnuplot)) written.push_back(file);
    print_summary(std::cout, run, options.program.filename().string(), written);
    std::cout.flush();
    return report_violations(std::cerr, run);
}

}  // namespace firtp::cli
