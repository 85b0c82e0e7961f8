#include "record_command.hpp"

#include "component_options.hpp"
#include "cli_errors.hpp"
#include "log_arguments.hpp"
#include "plan_run.hpp"
#include "number_text.hpp"
#include "record_config.hpp"
#include "replay_compare.hpp"
#include "replay_feed.hpp"
#include "replay_log.hpp"

#include <firtp/messages.hpp>
#include <firtp/in_process_component.hpp>
#include <firtp/text_cat.hpp>

#include <boost/program_options.hpp>
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

namespace firtp::cli {
namespace {

namespace po = boost::program_options;

struct ReplayOptions {
    std::filesystem::path log;
    double tolerance = 0.0;                       // relative (replay_compare.hpp); 0: bit for bit
    std::optional<std::filesystem::path> ini;     // another machine than the logged one
    std::optional<std::filesystem::path> module;  // firtp.so
    std::optional<int> run;                       // only this run of the log (1-based)
    bool help = false;
};

po::options_description replay_flags() {
    po::options_description d("Options", 100, 50);
    d.add_options()("help,h", "show this help and exit")(
        "tolerance", po::value<double>()->value_name("X"),
        "equal: every position, velocity and acceleration within X times max(1, |recorded value|) (default 0: bit "
        "for bit)")(
        "ini", po::value<std::string>()->value_name("FILE"),
        "run this machine instead of the logged one (for logs without FIRTP_CONFIG, or to see what an INI change does)")(
        "module", po::value<std::string>()->value_name("firtp.so"),
        "the HAL component to load (default: ../lib/firtp.so next to this program, or $FIRTP_MODULE)")(
        "run", po::value<int>()->value_name("N"),
        "replay only the log's Nth run of the component (a run starts where FIRTP_CONFIG's seq starts again)");
    return d;
}

ReplayOptions parse_replay_options(std::span<const std::string> args) {
    const po::variables_map vm = parse_log_arguments(replay_flags(), args, "replay");
    ReplayOptions o;
    o.help = vm.count("help") > 0;
    if (o.help) return o;
    o.log = vm["log"].as<std::string>();
    if (vm.count("tolerance") && !((o.tolerance = vm["tolerance"].as<double>()) >= 0.0))
        throw UsageError("--tolerance: must be 0 or a positive number");
    if (vm.count("ini")) o.ini = vm["ini"].as<std::string>();
    if (vm.count("module")) o.module = vm["module"].as<std::string>();
    if (vm.count("run") && (o.run = vm["run"].as<int>()) < 1) throw UsageError("--run: must be 1 or more");
    return o;
}

std::string replay_help() {
    std::ostringstream text;
    text << "Usage: firtp replay LOG.lcmlog [options]\n\n"
            "Runs the component again on a log recorded by `firtp record` (or `firtp run --lcm-log`): builds it\n"
            "from the log's FIRTP_CONFIG (machine and settings), steps it one servo period at a time, feeds it\n"
            "each logged FIRTP_BLOCK and FIRTP_CONTROL in the period the recorded component took it (each\n"
            "FIRTP_AXIS_STATE says so; inputs never taken go in where they were logged), and compares its axis\n"
            "states with the logged ones, one to one, printing where they first differ.\n\n"
         << replay_flags()
         << "\nExit status: 0 equal; 1 bad input (unreadable or incomplete log, no machine); 2 bad command line;\n"
            "4 the replayed axis states differ from the recorded ones (in any run).\n";
    return text.str();
}

// The axis states the replayed component publishes.
struct Collector {
    std::vector<firtp_lcm::axis_state_t> states;
    std::optional<std::string> problem;  // the first replayed state that was not intact (never expected)
    void on_state(const lcm::ReceiveBuffer* buffer, const std::string&) {
        const auto received = messages::receive<firtp_lcm::axis_state_t>(buffer->data, buffer->data_size);
        if (received.problem && !problem) problem = "replayed axis state: " + *received.problem;
        states.push_back(received.message);
    }
};

class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), shown_(isatty(STDERR_FILENO) != 0) {}
    void update(std::size_t done) {
        if (!shown_) return;
        const auto now = std::chrono::steady_clock::now();
        if (now - last_ < std::chrono::milliseconds(250)) return;
        last_ = now;
        std::cerr << "\rreplay: " << done << " of " << total_ << " axis states ("
                  << (total_ ? 100 * done / total_ : 100) << " %)" << std::flush;
    }
    void done() {
        if (shown_) std::cerr << "\r\033[K" << std::flush;
    }

private:
    std::size_t total_;
    bool shown_;
    std::chrono::steady_clock::time_point last_{};
};

void print_difference(std::ostream& out, const StateDifference& d, const LoggedRun& run,
                      const std::vector<firtp_lcm::axis_state_t>& replayed) {
    static const char axis_names[] = "XYZABCUVW";
    const std::size_t i = std::min(d.recorded, run.states.size() - 1);
    const firtp_lcm::axis_state_t& r = run.states[i];
    out << "first difference: " << messages::axis_state_channel << " seq " << r.seq << " (log event "
        << run.state_events[i] << ", tick " << r.tick << ", t = " << number_text(r.time) << " s, line " << r.line << ")";
    if (d.replayed < replayed.size()) out << ", replayed state " << d.replayed << " (tick " << replayed[d.replayed].tick << ")";
    out << ":\n  ";
    if (d.what == "missing")
        out << "the replay ended after " << replayed.size() << " states\n";
    else if (d.axis >= 0)
        out << d.what << " " << axis_names[d.axis] << ": recorded " << number_text(d.recorded_value) << ", replayed "
            << number_text(d.replayed_value) << " (difference " << number_text(d.replayed_value - d.recorded_value)
            << ")\n";
    else
        out << d.what << ": recorded " << number_text(d.recorded_value) << ", replayed " << number_text(d.replayed_value)
            << "\n";
}

}  // namespace

namespace {

// Replays one run; true when equal.
bool replay_run(const LoggedRun& run, const ReplayOptions& options) {
    LoggedComponent component;
    if (options.ini) {
        const std::vector<std::string> serve_args{"--ini", options.ini->string()};
        component.machine = module_machine(load_machine_config(parse_serve_options(serve_args).plan));
        if (run.config) component.settings = component_from(*run.config).settings;
        component.description = cat("--ini ", options.ini->string(), " (given)");
    } else if (run.config) {
        component = component_from(*run.config);
    } else {
        throw std::runtime_error(cat(options.log.string(), ": no FIRTP_CONFIG in the log, so its machine is unknown: "
                                     "record with `firtp record` beside `firtp serve` (or `firtp record --ini`), "
                                     "or give --ini"));
    }
    component.settings.plan_budget_us = 0;  // stepped: the planning a period does is not cut by the clock

    // The component on memq://, as `firtp run` builds it, stepped one period at a time.
    const auto lcm = messages::open("memq://");
    InProcessComponent chain(*lcm, component.machine, options.module.value_or(default_module_path()), component.settings);
    Collector collector;
    messages::keep_everything(lcm->subscribe(messages::axis_state_channel, &Collector::on_state, &collector));
    auto period = [&] {
        while (lcm->handleTimeout(0) > 0) {
        }
        chain.step();
        chain.poll();
        while (lcm->handleTimeout(0) > 0) {
        }
    };

    // Each input before the period the recording took it in (replay_feed.hpp).
    const FeedSchedule schedule = feed_schedule(run);
    const auto publish = [&](const std::vector<const LoggedEvent*>& inputs) {
        for (const LoggedEvent* e : inputs) lcm->publish(e->channel, e->data.data(), static_cast<unsigned>(e->data.size()));
    };
    Progress progress(run.states.size());
    // From the component's first period, as recorded: a log that starts later (the recorder
    // started a little after the component, nothing taken yet) skips the states before it.
    std::int64_t periods = 0;
    for (std::size_t i = 0; i < run.states.size(); ++i) {
        publish(schedule.before[i]);
        for (const std::int64_t wanted = run.states[i].tick + 1; periods < wanted; ++periods) period();
        progress.update(i);
    }
    progress.done();
    if (collector.problem) throw std::runtime_error(*collector.problem);
    const std::int64_t first_tick = run.states.front().tick;
    std::erase_if(collector.states, [&](const firtp_lcm::axis_state_t& s) { return s.tick < first_tick; });

    const Comparison c = compare_states(run.states, collector.states, component.machine.axes, options.tolerance);
    std::cout << "machine      " << component.description << "\n"
              << "log          " << run.blocks << " blocks, " << run.program_events << " program events, " << run.controls << " controls, " << run.states.size()
              << " axis states\n"
              << "fed          " << schedule.placed_by_state << " blocks and " << schedule.controls_placed_by_state
              << " controls in the periods the axis states name\n"
              << "replayed     " << collector.states.size() << " axis states in " << periods << " servo periods\n"
              << "compared     " << c.compared << " states, largest difference " << number_text(c.largest)
              << " (tolerance " << (options.tolerance > 0.0 ? number_text(options.tolerance) + " relative" : "0, bit for bit")
              << ")"
              << "\n";
    if (!c.first) {
        std::cout << "result       equal" << std::endl;
        return true;
    }
    std::cout << "result       DIFFERENT\n";
    print_difference(std::cout, *c.first, run, collector.states);
    std::cout.flush();
    return false;
}

}  // namespace

int replay_command(std::span<const std::string> args) {
    const ReplayOptions options = parse_replay_options(args);
    if (options.help) {
        std::cout << replay_help();
        return 0;
    }
    const std::vector<LoggedRun> runs = read_logged_runs(options.log, options.run);
    std::cout << "replay " << options.log.string() << "\n";
    int different = 0;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        if (runs.size() > 1 || options.run)
            std::cout << "run          " << (options.run ? *options.run : static_cast<int>(k + 1)) << " (log events "
                      << runs[k].first_event << "-" << runs[k].last_event << ")\n";
        for (const std::size_t i : runs[k].bridge_restarts)
            std::cout << "restart      of the bridge at FIRTP_AXIS_STATE log event " << runs[k].state_events[i] << " (tick "
                      << runs[k].states[i].tick << "): the component ran on, one run\n";
        different += replay_run(runs[k], options) ? 0 : 1;
    }
    if (runs.size() > 1)
        std::cout << "all runs     " << (different ? std::to_string(different) + " of " + std::to_string(runs.size()) + " DIFFERENT"
                                                    : std::to_string(runs.size()) + " equal")
                  << std::endl;
    return different ? exit_mismatch : 0;
}

}  // namespace firtp::cli
