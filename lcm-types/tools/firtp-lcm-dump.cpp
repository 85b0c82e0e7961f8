// firtp-lcm-dump: reads a .lcmlog (lcm-logger) and prints one line per event, or with --count a
// summary per channel with seq gaps. Messages whose crc does not match are marked CORRUPTED (and
// counted apart). LCM 1.3.1 ships no command-line spy.
#include "event_text.hpp"
#include "seq_summary.hpp"
#include <firtp/version.hpp>

#include <boost/program_options.hpp>
#include <lcm/lcm-cpp.hpp>

#include <iostream>
#include <regex>
#include <string>

namespace po = boost::program_options;

namespace {

struct Options {
    std::string log;
    std::string channel = ".*";
    bool count = false;
};

// False when the program should stop (help, or a usage error); code is then its exit code.
bool parse(int argc, char** argv, Options& options, int& code) {
    po::options_description visible("Usage: firtp-lcm-dump [options] LOG.lcmlog\nOptions");
    visible.add_options()
        ("help,h", "print this help")
        ("version", "print the version")
        ("channel,c", po::value(&options.channel), "only channels matching this regular expression (whole name)")
        ("count", po::bool_switch(&options.count), "print a summary per channel: events, seq range, gaps");
    po::options_description all;
    all.add(visible).add_options()("log", po::value(&options.log));
    po::positional_options_description positional;
    positional.add("log", 1);
    try {
        po::variables_map vm;
        po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
        po::notify(vm);
        if (vm.count("version") != 0) {
            std::cout << "firtp-lcm-dump " << firtp::version << "\n";
            code = 0;
            return false;
        }
        if (vm.count("help") != 0) {
            std::cout << visible;
            code = 0;
            return false;
        }
        if (options.log.empty()) throw po::error("no log file given");
    } catch (const po::error& e) {
        std::cerr << "firtp-lcm-dump: " << e.what() << "\n" << visible;
        code = 2;
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    int code = 0;
    if (!parse(argc, argv, options, code)) return code;

    std::regex channel;
    try {
        channel = std::regex(options.channel);
    } catch (const std::regex_error& e) {
        std::cerr << "firtp-lcm-dump: bad --channel '" << options.channel << "': " << e.what() << "\n";
        return 2;
    }
    lcm::LogFile log(options.log, "r");
    if (!log.good()) {
        std::cerr << "firtp-lcm-dump: cannot read " << options.log << "\n";
        return 1;
    }

    firtp::dump::SeqSummary summary;
    while (const lcm::LogEvent* event = log.readNextEvent()) {
        if (!std::regex_match(event->channel, channel)) continue;
        const firtp::dump::EventText line = firtp::dump::describe(event->data, event->datalen);
        if (options.count)
            summary.add(event->channel, line);
        else
            std::cout << event->timestamp << ' ' << event->channel << ' ' << line.text << '\n';
    }
    if (options.count) summary.print(std::cout);
    return 0;
}
