// What the measurement of a plan found beyond the machine's settings: corners above their
// tolerance (or, with TOLERANCE_MEANING contour, the path farther from the program than the
// tolerance), axis velocity, acceleration or jerk above the limits in the differences of the
// samples, an end off the program's last point. `firtp plan` and `firtp run` print each on stderr
// and exit with exit_check_failed, so a script can tell a bad trajectory from a bad input.
#pragma once

#include "plan_run.hpp"

#include <string>
#include <vector>

namespace firtp::cli {

std::vector<std::string> measured_violations(const PlanRun& run);

// Prints them as "firtp: measured: ..." on `err`; the exit status for them (0 when none).
int report_violations(std::ostream& err, const PlanRun& run);

}  // namespace firtp::cli
