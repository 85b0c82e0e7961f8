#include "run_command.hpp"

#include "component_options.hpp"
#include "gnuplot_pipe.hpp"
#include "number_text.hpp"
#include "plan_checks.hpp"
#include "plan_outputs.hpp"
#include "plan_run.hpp"
#include "plan_sink.hpp"
#include "progress_line.hpp"
#include "record_config.hpp"
#include <firtp/recorded_states.hpp>
#include <firtp/in_process_component.hpp>
#include "summary.hpp"

#include <firtp/host.hpp>
#include <firtp/lcm_recorder.hpp>
#include <firtp/text_cat.hpp>
#include <firtp/messages.hpp>

#include <iostream>
#include <stdexcept>

namespace firtp::cli {

int run_command(std::span<const std::string> args) {
    const ComponentOptions options = parse_run_options(args);
    if (options.plan.help) {
        std::cout << run_help();
        return 0;
    }
    const std::optional<std::filesystem::path> gnuplot =
        options.plan.plot ? std::optional(find_gnuplot()) : std::nullopt;

    // The plan of the same program gives the corner decisions for the report and the reference.
    PlanRun run = run_plan(options.plan);
    const std::vector<AxisState> planned = run.trajectory.samples;

    const auto lcm = messages::open(options.lcm_url.empty() ? "memq://" : options.lcm_url);
    std::optional<LcmRecorder> recorder;
    if (options.lcm_log) recorder.emplace(*lcm, *options.lcm_log);
    const InProcessSettings settings;
    firtp::InProcessComponent chain(*lcm, run.machine, options.module.value_or(firtp::default_module_path()), settings);
    // The machine first in the log, so that `firtp replay` needs nothing else.
    ConfigPublisher config(*lcm, config_message("run", args, options, run.machine, settings));
    host::HostOptions host_options;
    host_options.record_axis_states = true;
    host::Host host(*lcm, run.program, host_options);

    // One servo period per round: the host publishes, LCM delivers, the component runs, the
    // bridge publishes axis state and status for the host's next round.
    const std::size_t limit = 4 * planned.size() + 100000;
    host::Result result = host::Result::running;
    ProgressLine progress("run", run.program.blocks.size());
    for (std::size_t k = 0; k < limit && result == host::Result::running; ++k) {
        result = host.step();
        while (lcm->handleTimeout(0) > 0) {
        }
        chain.step();
        chain.poll();
        progress.update(static_cast<std::size_t>(host.statistics().blocks_published), static_cast<double>(k) * run.parameters.period);
    }
    progress.clear();
    if (result != host::Result::done)
        throw std::runtime_error(cat("run: the program did not complete (", host::to_string(result), "): ",
                                     host.error()));

    // The received samples go through what `plan` does with its own: CSV, measurement, plot.
    const std::vector<AxisState> received = firtp::samples_from_axis_states(host.axis_states(), run.parameters.period);
    run.trajectory.samples.clear();
    PlanOutputs outputs(options.plan);
    PlanSink sink(run, outputs.csv(), nullptr, false);
    for (const AxisState& s : received) sink.sample(s);
    run.sample_count = received.size();
    sink.finish();
    double difference = 0.0;
    const std::size_t common = std::min(planned.size(), received.size());
    for (std::size_t k = 0; k < common; ++k)
        difference = std::max(difference, (planned[k].position - received[k].position).norm());

    const std::vector<std::filesystem::path> written = outputs.finish(run, sink.plot(), gnuplot);
    print_summary(std::cout, run, options.plan.program.filename().string(), written);
    const host::Statistics stats = host.statistics();
    std::cout << "chain        " << run.program.blocks.size() << " blocks over LCM (" << stats.blocks_published
              << " published, " << stats.go_backs << " resends), " << stats.axis_states
              << " axis states back; samples " << received.size() << " vs planned " << planned.size()
              << ", largest difference from the plan " << number_text(difference) << " mm\n";
    std::cout.flush();
    return report_violations(std::cerr, run);
}

}  // namespace firtp::cli
