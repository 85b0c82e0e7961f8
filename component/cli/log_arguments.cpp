#include "log_arguments.hpp"

#include "cli_errors.hpp"

#include <vector>

namespace firtp::cli {

namespace po = boost::program_options;

po::variables_map parse_log_arguments(po::options_description flags, std::span<const std::string> args,
                                      const std::string& command) {
    flags.add_options()("log", po::value<std::string>());
    po::positional_options_description positional;
    positional.add("log", 1);
    po::variables_map vm;
    try {
        po::store(po::command_line_parser(std::vector<std::string>(args.begin(), args.end()))
                      .options(flags).positional(positional).run(), vm);
        po::notify(vm);
    } catch (const po::error& e) {
        throw UsageError(std::string(e.what()) + " (see firtp " + command + " --help)");
    }
    if (!vm.count("help") && !vm.count("log"))
        throw UsageError(command + ": missing LOG.lcmlog (see firtp " + command + " --help)");
    return vm;
}

}  // namespace firtp::cli
