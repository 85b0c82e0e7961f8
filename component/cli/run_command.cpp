#include "run_command.hpp"

#include "component_options.hpp"
#include "gnuplot_pipe.hpp"
#include "number_text.hpp"
#include "output_files.hpp"
#include "plan_checks.hpp"
#include "plan_outputs.hpp"
#include "plan_run.hpp"
#include "plan_sink.hpp"
#include "record_config.hpp"
#include "run_chain.hpp"
#include "summary.hpp"

#include <firtp/host.hpp>
#include <firtp/in_process_component.hpp>
#include <firtp/lcm_recorder.hpp>
#include <firtp/messages.hpp>

#include <iostream>
#include <limits>

namespace firtp::cli {
namespace {

// The chain is given four periods for every planned sample, and 100,000 more.
std::size_t period_limit(std::size_t planned) { return 4 * planned + 100000; }

// The reference plan of the same program, made alongside the chain: each planned sample waits for
// the received sample of the same index (the chain runs until it comes) and is compared with it;
// the corner reports go to the received samples' sink, which measures against them.
class Reference : public TrajectorySink {
public:
    Reference(RunChain& chain, PlanSink& received, PlanDifference& difference)
        : chain_(chain), received_(received), difference_(difference) {}

    void sample(const AxisState& state) override {
        ++planned_;
        difference_.planned(state.position);
        if (!chain_.running()) return;
        chain_.run_until(planned_, period_limit(planned_));
        if (chain_.running()) return;
        chain_.finish();
        difference_.received_done();
    }
    void corner(const CornerReport& report) override { received_.corner(report); }

private:
    RunChain& chain_;
    PlanSink& received_;
    PlanDifference& difference_;
    std::size_t planned_ = 0;
};

}  // namespace

int run_command(std::span<const std::string> args) {
    const ComponentOptions options = parse_run_options(args);
    if (options.plan.help) {
        std::cout << run_help();
        return 0;
    }
    const std::optional<std::filesystem::path> gnuplot =
        options.plan.plot ? std::optional(find_gnuplot()) : std::nullopt;

    // The program read once into a spool: the host sends it from there, the reference plan and the
    // measurement read it back as they go.
    PlanRun run = prepare_spooled_plan(options.plan);

    const auto lcm = messages::open(options.lcm_url.empty() ? "memq://" : options.lcm_url);
    // The log too is written beside its target and renamed when the run is over: a program the
    // planner refuses half-way leaves nothing behind.
    OutputFiles log_file;
    std::optional<LcmRecorder> recorder;
    if (options.lcm_log) recorder.emplace(*lcm, log_file.create(*options.lcm_log));
    const InProcessSettings settings;
    firtp::InProcessComponent component(*lcm, run.machine, options.module.value_or(firtp::default_module_path()), settings);
    // The machine first in the log, so that `firtp replay` needs nothing else.
    ConfigPublisher config(*lcm, config_message("run", args, options, run.machine, settings));

    // The received samples go through what `plan` does with its own, as they arrive: CSV,
    // measurement, plot.
    PlanOutputs outputs(options.plan);
    PlanSink sink(run, outputs.csv(), nullptr, false, options.plan.plot.has_value());
    PlanDifference difference;
    host::HostOptions host_options;
    RunChain chain(*lcm, component, run, host_options, [&](const AxisState& s) {
        sink.sample(s);
        difference.received(s.position);
    });
    Reference reference(chain, sink, difference);
    plan_program(run, reference);
    const std::size_t planned = run.sample_count;
    difference.planned_done();
    chain.run_until(std::numeric_limits<std::size_t>::max(), period_limit(planned));
    chain.finish();
    run.sample_count = chain.received();
    sink.finish();

    const std::vector<std::filesystem::path> written = outputs.finish(run, sink.plot(), gnuplot);
    recorder.reset();
    log_file.commit();
    print_summary(std::cout, run, options.plan.program.filename().string(), written);
    const host::Statistics stats = chain.host().statistics();
    std::cout << "chain        " << run.blocks << " blocks over LCM (" << stats.blocks_published << " published, "
              << stats.go_backs << " resends), " << stats.axis_states << " axis states back; samples "
              << chain.received() << " vs planned " << planned << ", largest difference from the plan "
              << number_text(difference.largest()) << " mm\n";
    std::cout.flush();
    return report_violations(std::cerr, run);
}

}  // namespace firtp::cli
