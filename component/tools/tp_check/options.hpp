// firtp-tp-check's command line (see main.cpp for what each option checks).
#pragma once

#include <string>
#include <vector>

namespace firtp::tp_check {

struct Options {
    std::string samples_path, ini_path, program_path, tp_samples_path, json_path, reference_path;
    double within = 1e-9;              // --within: mm from the reference
    double tolerance = -1.0;           // --tolerance: contour error, mm (< 0: not checked)
    double corner_tolerance = -1.0;    // --corner-tolerance: corner errors, mm (< 0: not checked)
    double jerk = -1.0;                // --jerk: every axis' jerk (<= 0: not checked)
    double tsc_hz = 0.0;               // --tsc-hz: the time-stamp counter's frequency (0: measured)
    double cycle_time = -1.0;          // --cycle-time S (<= 0: not checked)
    double cycle_within = 0.002;       // --cycle-time S:WITHIN
    std::vector<long> expected_lines;  // --lines
    bool limits = false;               // --limits
    bool stopped = false;              // --stopped
    double hold = -1.0;                // --hold S (<= 0: not checked)
};

// Prints why and the usage to stderr, exits 2.
[[noreturn]] void usage(const std::string& why);

// The options after the program name; SAMPLES, --ini and --program are needed (else usage()).
Options parse_options(const std::vector<std::string>& args);

}  // namespace firtp::tp_check
