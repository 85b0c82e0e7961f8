// The short human summary `firtp plan` prints on stdout.
#pragma once

#include "plan_run.hpp"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace firtp::cli {

void print_summary(std::ostream& out, const PlanRun& run, const std::string& program_name,
                   const std::vector<std::filesystem::path>& written);

}  // namespace firtp::cli
