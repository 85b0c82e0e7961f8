// Errors the firtp command reports on stderr as "firtp: <what>".
#pragma once

#include <stdexcept>

namespace firtp::cli {

constexpr int exit_input_error = 1;  // bad program, INI, I/O, missing tool
constexpr int exit_usage_error = 2;  // bad command line
constexpr int exit_check_failed = 3;  // the measured trajectory breaks a tolerance, a limit or the end (plan_checks.hpp)
constexpr int exit_mismatch = 4;      // record: messages missing, repeated or corrupted; replay: states differ

// The command line is wrong: unknown flag, bad flag value, missing argument.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace firtp::cli
