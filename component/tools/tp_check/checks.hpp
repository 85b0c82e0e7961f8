// firtp-tp-check's checks: each failure a sentence (the exit status is 1 when there is any).
#pragma once

#include "options.hpp"
#include "recording.hpp"

#include <firtp/machine.hpp>
#include <firtp/measure.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace firtp::tp_check {

// What was measured of the motion, for the checks and the report.
struct Measurement {
    Recording recording;
    Motion motion;
    std::vector<AxisState> samples;  // the motion's
    Measured measured;               // component/analysis's measurement against the program
    double end_error = 0.0;          // mm from the program's end at the last sample
    double longest_rest = 0.0;       // s, inside the motion
    std::vector<long> lines;         // program lines while moving
};

// The sampler, the end point, tolerances, limits, the offline plan (--reference: every period
// equal to it within --within, as many of them; printed and added to `report`), hold, cycle time
// and lines, as the options ask.
std::vector<std::string> check_motion(const Options& o, const MachineConfig& machine, const Measurement& m,
                                      nlohmann::json& report);

}  // namespace firtp::tp_check
