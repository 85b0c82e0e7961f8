// What firtp-tp-check reads: halsampler's recording of LinuxCNC's servo periods (record.hal),
// firtp_tp's own pins (--tp-samples) and `firtp plan --csv` (--reference).
#pragma once

#include <firtp/types.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace firtp::tp_check {

// One servo period of record.hal: X Y Z (scaled by 2^40), motion.program-line, the TSC clocks of
// motion-controller and motion-command-handler, motion.in-position.
struct Row {
    AxisVector position = AxisVector::Zero();
    long line = 0;
    double controller_clocks = 0.0;
    double command_clocks = 0.0;
    bool in_position = false;
};

struct Recording {
    std::vector<Row> rows;  // at least two
    long overruns = 0;      // "overrun" lines: periods the sampler lost
};

// usage() on a file that cannot be read, a short line or fewer than two samples.
Recording read_recording(const std::string& path);

// The motion: from the last sample at rest before it to the first at rest at its end.
struct Motion {
    std::size_t first = 0, last = 0;
};
Motion find_motion(const std::vector<Row>& rows);

// The motion's samples, time from 0 in steps of `period`.
std::vector<AxisState> motion_samples(const std::vector<Row>& rows, Motion motion, double period);

// The longest rest inside the motion (a pause), in seconds.
double longest_rest(const std::vector<Row>& rows, Motion motion, double period);

// Program lines while moving, each once in the order they came.
std::vector<long> lines_while_moving(const std::vector<Row>& rows, Motion motion);

// The points of `firtp plan --csv` (t,x,y,z,...), one a period; usage() when it cannot be read.
std::vector<AxisVector> read_reference(const std::string& path);

// Median, 99th percentile and largest of a set of times (us).
struct Stats {
    double median = 0.0, p99 = 0.0, max = 0.0;
    std::size_t count = 0;
};
Stats stats(std::vector<double> v);
nlohmann::json stats_json(const Stats& s);

// CPU time of motion-controller and motion-command-handler over the motion, us.
struct MotionCpu {
    Stats controller, command;
};
MotionCpu motion_cpu(const std::vector<Row>& rows, Motion motion, double tsc_hz);

// firtp_tp's own measurements (--tp-samples): per add (periods whose add counter moved) and per cycle.
nlohmann::json firtp_tp_report(const std::string& path);

// The time-stamp counter's frequency (what HAL's .time counts), measured over 0.3 s; 0 off x86.
double measure_tsc_hz();

}  // namespace firtp::tp_check
