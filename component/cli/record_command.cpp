#include "record_command.hpp"

#include "component_options.hpp"
#include "cli_errors.hpp"
#include "log_arguments.hpp"
#include "plan_run.hpp"
#include "record_config.hpp"
#include "record_receiver.hpp"

#include <event_text.hpp>
#include <seq_summary.hpp>
#include <firtp/messages.hpp>
#include <firtp/text_cat.hpp>

#include <boost/program_options.hpp>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

namespace firtp::cli {
namespace {

namespace po = boost::program_options;
using Clock = std::chrono::steady_clock;

struct RecordOptions {
    std::filesystem::path log;
    std::string url;
    std::string channels = ".*";
    double duration = 0.0;  // 0: until interrupted
    double idle = 0.0;      // stop once nothing arrived for this long after the first message (0: never)
    std::optional<std::filesystem::path> ini;
    bool help = false;
};

po::options_description record_flags() {
    po::options_description d("Options", 100, 50);
    d.add_options()("help,h", "show this help and exit")(
        "lcm-url", po::value<std::string>()->value_name("URL"),
        "LCM provider (LCM's default group, this host only; udpm:// gets a 64 MiB receive buffer unless it names one)")(
        "channels", po::value<std::string>()->value_name("REGEX"), "record only channels matching this (.*: all)")(
        "duration", po::value<double>()->value_name("S"), "stop after S seconds")(
        "idle", po::value<double>()->value_name("S"), "stop once nothing arrived for S seconds (after the first message)")(
        "ini", po::value<std::string>()->value_name("FILE"),
        "write the machine of this INI (as `firtp serve --ini FILE` runs it) as the log's first event, for a "
        "component that does not publish FIRTP_CONFIG itself");
    return d;
}

RecordOptions parse_record_options(std::span<const std::string> args) {
    const po::variables_map vm = parse_log_arguments(record_flags(), args, "record");
    RecordOptions o;
    o.help = vm.count("help") > 0;
    if (o.help) return o;
    o.log = vm["log"].as<std::string>();
    if (vm.count("lcm-url")) o.url = vm["lcm-url"].as<std::string>();
    if (vm.count("channels")) o.channels = vm["channels"].as<std::string>();
    if (vm.count("ini")) o.ini = vm["ini"].as<std::string>();
    if (vm.count("duration") && !((o.duration = vm["duration"].as<double>()) > 0.0))
        throw UsageError("--duration: must be a positive number of seconds");
    if (vm.count("idle") && !((o.idle = vm["idle"].as<double>()) > 0.0))
        throw UsageError("--idle: must be a positive number of seconds");
    return o;
}

std::string record_help() {
    std::ostringstream text;
    text << "Usage: firtp record LOG.lcmlog [options]\n\n"
            "Records every LCM message into an LCM log (lcm-logger's format) without losing any: one thread only\n"
            "receives, another writes. Checks the sequence numbers of every firtp stream and prints per channel how\n"
            "many messages it saw and how many were missing, repeated, reordered or corrupted. Stops on Ctrl-C,\n"
            "--duration or --idle. `firtp replay LOG` runs the component again on what was recorded.\n\n"
         << record_flags()
         << "\nExit status: 0 nothing lost; 1 bad input; 2 bad command line; 4 messages missing, repeated or corrupted\n"
            "(repeated blocks are the host's resends and do not count).\n";
    return text.str();
}

std::atomic<bool> stop_requested{false};
extern "C" void request_record_stop(int) { stop_requested = true; }

// Writes events in order and keeps the seq accounting.
class LogWriter {
public:
    explicit LogWriter(const std::filesystem::path& file) : log_(file.string(), "w") {
        if (!log_.good()) throw std::runtime_error(cat("cannot write the LCM log '", file.string(), "'"));
    }
    void write(const std::string& channel, std::int64_t utime, const std::vector<std::uint8_t>& data) {
        lcm::LogEvent event;
        event.eventnum = events_++;
        event.timestamp = utime;
        event.channel = channel;
        event.datalen = static_cast<std::int32_t>(data.size());
        event.data = const_cast<std::uint8_t*>(data.data());
        if (log_.writeEvent(&event) != 0) throw std::runtime_error("cannot write the LCM log (disk full?)");
        summary_.add(channel, dump::describe(data.data(), static_cast<int>(data.size())));
    }
    void flush() { std::fflush(log_.getFilePtr()); }
    std::int64_t events() const { return events_; }
    const dump::SeqSummary& summary() const { return summary_; }

private:
    lcm::LogFile log_;
    std::int64_t events_ = 0;
    dump::SeqSummary summary_;
};

// Per channel: events and what the seq numbers say; true when nothing was lost.
bool print_totals(std::ostream& out, const dump::SeqSummary& summary) {
    bool complete = true;
    for (const auto& [channel, t] : summary.totals()) {
        const bool blocks = channel == messages::block_channel;  // repeats there are the host's resends
        const bool lost = t.missing > 0 || t.corrupted > 0 || (!blocks && t.repeated > 0);
        complete = complete && !lost;
        out << "  " << channel << ": " << t.events << " messages, missing " << t.missing << ", repeated "
            << t.repeated << (blocks ? " (resends)" : "") << ", reordered " << t.reordered << ", corrupted "
            << t.corrupted;
        if (t.unknown > 0) out << ", " << t.unknown << " not firtp (not checked)";
        out << (lost ? "  LOST" : "") << "\n";
    }
    return complete;
}

}  // namespace

int record_command(std::span<const std::string> args) {
    const RecordOptions options = parse_record_options(args);
    if (options.help) {
        std::cout << record_help();
        return 0;
    }
    LogWriter writer(options.log);
    if (options.ini) {  // the log's first event: the machine as `firtp serve --ini FILE` runs it
        const std::vector<std::string> serve_args{"--ini", options.ini->string()};
        const ComponentOptions serve = parse_serve_options(serve_args);
        const MachineConfig machine = load_machine_config(serve.plan);
        firtp_lcm::config_t config =
            config_message("serve", serve_args, serve, machine, serve_component_settings(machine, serve.queue));
        config.seq = 1;
        config.utime = messages::now_utime();
        writer.write(messages::config_channel, config.utime, messages::seal_encoded(config));
    }
    const std::string url = recording_url(options.url);
    RecordReceiver receiver(url, options.channels);
    std::signal(SIGINT, request_record_stop);
    std::signal(SIGTERM, request_record_stop);
    std::cerr << "firtp record: recording " << options.channels << " on " << url << " into " << options.log.string()
              << std::endl;

    const bool progress = isatty(STDERR_FILENO) != 0;
    const Clock::time_point begin = Clock::now();
    Clock::time_point last_message = begin, last_progress = begin;
    bool any = false;
    std::vector<ReceivedEvent> batch;
    for (;;) {
        batch.clear();
        receiver.take(batch, 100);
        const Clock::time_point now = Clock::now();
        for (const ReceivedEvent& e : batch) writer.write(e.channel, e.utime, e.data);
        if (!batch.empty()) {
            writer.flush();
            last_message = now;
            any = true;
        }
        if (progress && now - last_progress >= std::chrono::seconds(1)) {
            std::cerr << "\rrecorded " << writer.events() << " messages" << std::flush;
            last_progress = now;
        }
        if (stop_requested) break;
        if (options.duration > 0.0 && now - begin >= std::chrono::duration<double>(options.duration)) break;
        if (options.idle > 0.0 && any && now - last_message >= std::chrono::duration<double>(options.idle)) break;
    }
    receiver.stop();
    batch.clear();
    receiver.take(batch, 0);
    for (const ReceivedEvent& e : batch) writer.write(e.channel, e.utime, e.data);
    if (progress) std::cerr << "\r";

    std::cout << "firtp record: " << writer.events() << " messages in " << options.log.string() << "\n";
    const bool complete = print_totals(std::cout, writer.summary());
    if (const int restarts = writer.summary().restarts(); restarts > 0)
        std::cout << "the component started again " << restarts << (restarts == 1 ? " time" : " times")
                  << " (FIRTP_CONFIG's seq): counted per run, `firtp replay` replays each\n";
    if (complete) {
        std::cout << "nothing lost\n" << std::flush;
    } else {  // which seq numbers, per channel and program (as firtp-lcm-dump --count)
        std::cout << "messages were lost (LOST above); seq numbers seen:\n";
        writer.summary().print(std::cout);
        std::cout.flush();
    }
    return complete ? 0 : exit_mismatch;
}

}  // namespace firtp::cli
