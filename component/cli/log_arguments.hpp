// The command line of the commands that take one LCM log (record, replay): their flags and the
// log as the one positional argument.
#pragma once

#include <boost/program_options.hpp>

#include <span>
#include <string>

namespace firtp::cli {

// Parses `args` with `flags` plus LOG.lcmlog; a bad or missing argument is a UsageError naming
// `command`. With --help the log may be missing.
boost::program_options::variables_map parse_log_arguments(boost::program_options::options_description flags,
                                                         std::span<const std::string> args, const std::string& command);

}  // namespace firtp::cli
