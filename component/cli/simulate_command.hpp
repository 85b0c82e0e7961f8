// `firtp simulate`: firtp tuned, untuned and an S-curve planner driving the machine's modes.
#pragma once

#include <span>
#include <string>

namespace firtp::cli {

// Arguments after "simulate". Returns the exit status; throws UsageError or input errors (see main).
int simulate_command(std::span<const std::string> args);

}  // namespace firtp::cli
