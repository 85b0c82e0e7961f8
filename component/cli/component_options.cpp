#include "component_options.hpp"

#include "cli_errors.hpp"

#include <sstream>

namespace firtp::cli {
namespace {

namespace po = boost::program_options;

po::options_description transport_flags(bool with_module) {
    po::options_description d("Transport", 100, 50);
    d.add_options()("lcm-url", po::value<std::string>()->value_name("URL"),
                    "LCM provider, e.g. udpm://239.255.76.67:7667?ttl=0 (LCM's default group, this host only)");
    if (with_module)
        d.add_options()("module", po::value<std::string>()->value_name("firtp.so"),
                        "the HAL component to load (default: $FIRTP_MODULE, else ../lib/firtp/firtp.so or ../lib/firtp.so next to this program)");
    return d;
}

po::options_description help_flag() {
    po::options_description d("Options", 100, 50);
    d.add_options()("help,h", "show this help and exit");
    return d;
}

void read_transport(const po::variables_map& vm, ComponentOptions& o) {
    if (vm.count("lcm-url")) o.lcm_url = vm["lcm-url"].as<std::string>();
    if (vm.count("module")) o.module = vm["module"].as<std::string>();
}

po::options_description run_flags() {
    po::options_description d = help_flag();
    d.add(machine_flags()).add(output_flags()).add(transport_flags(true));
    d.add_options()("lcm-log", po::value<std::string>()->value_name("FILE.lcmlog"),
                    "record every LCM message of the run (blocks, control, status, axis states) into an LCM "
                    "log, as lcm-logger would; tests/replay/*.lcmlog are made this way");
    return d;
}

po::options_description serve_flags() {
    po::options_description d = help_flag();
    d.add_options()("exit-when-done", "exit once a program has run to its end (or failed)")(
        "duration", po::value<double>()->value_name("S"), "exit after S seconds")(
        "rt-prio", po::value<int>()->value_name("N"),
        "servo thread SCHED_FIFO priority 1-99 where the system allows it (80; 0: normal scheduling)")(
        "queue", po::value<int>()->value_name("N"),
        "blocks the component holds, planned ahead (1024); a host may send that many beyond the running one");
    d.add(machine_flags()).add(transport_flags(true));
    return d;
}

po::options_description host_flags() {
    po::options_description d = help_flag();
    d.add_options()("csv", po::value<std::string>()->value_name("FILE"),
                    "record every FIRTP_AXIS_STATE and write them as `firtp plan --csv` does")(
        "max-feed", po::value<double>()->value_name("X"), "highest feed override the keys may set (1.5)");
    d.add(machine_flags()).add(transport_flags(false));
    return d;
}

}  // namespace

ComponentOptions parse_run_options(std::span<const std::string> args) {
    const po::variables_map vm = parse_flags(args, run_flags(), "run", true);
    ComponentOptions o;
    read_machine_flags(vm, o.plan);
    read_output_flags(vm, o.plan);
    read_transport(vm, o);
    if (vm.count("lcm-log")) o.lcm_log = vm["lcm-log"].as<std::string>();
    return o;
}

ComponentOptions parse_serve_options(std::span<const std::string> args) {
    const po::variables_map vm = parse_flags(args, serve_flags(), "serve", false);
    ComponentOptions o;
    read_machine_flags(vm, o.plan);
    read_transport(vm, o);
    o.exit_when_done = vm.count("exit-when-done") > 0;
    if (vm.count("rt-prio")) {
        o.rt_priority = vm["rt-prio"].as<int>();
        if (o.rt_priority < 0 || o.rt_priority > 99) throw UsageError("--rt-prio: must be 0 (normal scheduling) or 1-99");
    }
    if (vm.count("queue")) {
        o.queue = vm["queue"].as<int>();
        if (o.queue < 1 || o.queue > 10'000'000) throw UsageError("--queue: must be 1-10000000 blocks");
    }
    if (vm.count("duration")) {
        o.duration = vm["duration"].as<double>();
        if (!(o.duration > 0.0)) throw UsageError("--duration: must be a positive number of seconds");
    }
    return o;
}

ComponentOptions parse_host_options(std::span<const std::string> args) {
    const po::variables_map vm = parse_flags(args, host_flags(), "host", true);
    ComponentOptions o;
    read_machine_flags(vm, o.plan);
    read_transport(vm, o);
    if (vm.count("csv")) o.plan.csv = vm["csv"].as<std::string>();
    if (vm.count("max-feed")) {
        o.max_feed = vm["max-feed"].as<double>();
        if (!(o.max_feed > 0.0)) throw UsageError("--max-feed: must be a positive factor");
    }
    return o;
}

std::string run_help() {
    std::ostringstream text;
    text << "Usage: firtp run PROGRAM.ngc [options]\n\n"
            "Runs the whole chain in this process: the host stub reads the program and streams its blocks\n"
            "over LCM (memq:// unless --lcm-url) to firtp-bridge, which feeds the firtp HAL component running\n"
            "on a hal-shim servo thread; the axis states come back over LCM and are written like\n"
            "`firtp plan` writes its outputs. The trajectory equals the planned one.\n\n"
         << run_flags() << "\nExit status: 0 success, 1 bad input or the component failed, 2 bad command line.\n";
    return text.str();
}

std::string serve_help() {
    std::ostringstream text;
    text << "Usage: firtp serve [options]\n\n"
            "Runs the firtp HAL component on a real-time servo thread (hal-shim) with firtp-bridge on LCM,\n"
            "waiting for `firtp host` (or any publisher of FIRTP_BLOCK) in another process.\n\n"
         << serve_flags() << "\nExit status: 0 success, 1 failure, 2 bad command line.\n";
    return text.str();
}

std::string host_help() {
    std::ostringstream text;
    text << "Usage: firtp host PROGRAM.ngc [options]\n\n"
            "Streams the program's blocks over LCM to a running component (firtp serve) with flow control,\n"
            "shows progress and takes keys: + / - feed override, space hold/resume, a abort, q abort and quit\n"
            "(or lines on stdin when it is not a terminal: feed 0.8, hold, resume, abort).\n\n"
         << host_flags() << "\nExit status: 0 done, 1 failed or aborted, 2 bad command line, 3 lost contact.\n";
    return text.str();
}

}  // namespace firtp::cli
