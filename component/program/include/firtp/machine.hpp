// The machine a program runs on: servo period, axis limits, filter times and tolerance.
#pragma once

#include <firtp/ini.hpp>
#include <firtp/parameters.hpp>

#include <optional>
#include <vector>

namespace firtp {

struct MachineConfig {
    double period = 0.001;                  // [EMCMOT]SERVO_PERIOD (ns in the INI)
    MachineLimits limits;                   // [TRAJ]MAX_LINEAR_VELOCITY, [AXIS_<L>]MAX_VELOCITY/ACCELERATION/JERK
    int stages = 2;                         // [FIRTP]STAGES
    std::vector<double> given_times;        // [FIRTP]T1..T4 in s (0 = derive from limits)
    std::vector<double> mode_frequencies;   // [FIRTP]MODES, Hz, space separated
    double default_tolerance = 0.05;        // [FIRTP]TOLERANCE, used by G64 without P
    ToleranceMeaning tolerance_meaning = ToleranceMeaning::corner_point;  // [FIRTP]TOLERANCE_MEANING corner|contour
    double arc_chord_tolerance = 0.001;     // [FIRTP]ARC_CHORD_TOLERANCE, mm: largest sagitta of an arc's chords
    double max_feed_override = 1.0;         // [DISPLAY]MAX_FEED_OVERRIDE: limits hold up to this feed scale
    double rate_reserve = 0.2;              // [FIRTP]RATE_RESERVE: share of a and j limits kept for override ramps

    FilterTimes filter_times() const;       // filter_times_from_limits(limits, stages, given_times, mode_frequencies)
    PlannerParameters planner_parameters() const;
};

// Built-in machine used when no INI is given: X Y Z at 300 mm/s, 5000 mm/s^2, 100000 mm/s^3,
// 1 ms servo period, two stages (T1 = 60 ms, T2 = 50 ms), 0.05 mm tolerance, 0.001 mm arc chords.
MachineConfig default_machine();

// Reads the keys above over default_machine(). Throws ConfigError naming file, line and key for a
// value that is not a number, is out of range (zero, negative, NaN) or a [FIRTP] key it does not know.
MachineConfig load_machine(const IniFile& ini);

// Command-line overrides (--t1 --t2 --tolerance --period), each validated like the INI keys;
// throws ConfigError naming the flag.
struct MachineOverrides {
    std::optional<double> t1, t2, tolerance, period;
};
void apply_overrides(MachineConfig& machine, const MachineOverrides& overrides);

}  // namespace firtp
