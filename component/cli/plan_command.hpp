// `firtp plan`: plan a G-code program and write CSV / JSON / PNG and a summary.
#pragma once

#include <span>
#include <string>

namespace firtp::cli {

// Arguments after "plan". Returns the exit status; throws UsageError or input errors (see main).
int plan_command(std::span<const std::string> args);

}  // namespace firtp::cli
