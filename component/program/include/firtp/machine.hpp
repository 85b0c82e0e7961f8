// The machine a program runs on: servo period, axis limits, filter times and tolerance.
#pragma once

#include <firtp/ini.hpp>
#include <firtp/mode_tuning.hpp>
#include <firtp/parameters.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace firtp {

// Blocks a program may expand to (an arc: one a chord) unless [FIRTP]MAX_PROGRAM_BLOCKS says
// otherwise: 10x the 10^6-block programs the benchmarks plan. 120 bytes a block: 1.2 GB (1.8 GB
// peak measured while the vector grew, at 112 bytes a block before Block::dwell).
constexpr std::size_t default_max_program_blocks = 10'000'000;

struct MachineConfig {
    double period = 0.001;                  // [EMCMOT]SERVO_PERIOD (ns in the INI)
    MachineLimits limits;                   // [TRAJ]MAX_LINEAR_VELOCITY, [AXIS_<L>]MAX_VELOCITY/ACCELERATION/JERK
    int stages = 2;                         // [FIRTP]STAGES
    std::vector<double> given_times;        // [FIRTP]T1..T4 in s (0 = derive from limits)
    ModeTuning tuning;                      // [FIRTP]MODES (Hz[/damping], X: for one axis) and ROBUST
    double default_tolerance = 0.05;        // [FIRTP]TOLERANCE, used by G64 without P
    ToleranceMeaning tolerance_meaning = ToleranceMeaning::corner_point;  // [FIRTP]TOLERANCE_MEANING corner|contour
    double arc_chord_tolerance = 0.001;     // [FIRTP]ARC_CHORD_TOLERANCE, mm: largest sagitta of an arc's chords
    double max_feed_override = 1.0;         // [DISPLAY]MAX_FEED_OVERRIDE: limits hold up to this feed scale
    double rate_reserve = 0.2;              // [FIRTP]RATE_RESERVE: fixed chain: share of a and j kept for override ramps
    std::size_t max_program_blocks = default_max_program_blocks;  // [FIRTP]MAX_PROGRAM_BLOCKS (whole, >= 1)
    // For LinuxCNC's interpreter (gcode.hpp): the INI it reads ([RS274NGC] SUBROUTINE_PATH,
    // startup codes, ...), [RS274NGC]PARAMETER_FILE and [EMCIO]TOOL_TABLE, the last two relative
    // to the INI's folder as LinuxCNC (started there) reads them. Empty: none.
    std::filesystem::path ini_file, parameter_file, tool_table;
    std::string startup_code;  // [RS274NGC]RS274NGC_STARTUP_CODE: run before every program, as LinuxCNC's task does

    // The paper's fixed chain: filter times given ([FIRTP]T1..T4) or tuned to [FIRTP]MODES.
    // Otherwise every move is smoothed at the axis limits and the filter times are not used.
    bool fixed_chain() const;
    // Untuned without modes: given times, else T1 = max v/a, T2 = max a/j (filter_times_from_limits).
    // With modes: tuned to them at the smallest delay, those times as lower bounds (tune_filter_times).
    FilterTimes filter_times() const;
    TunedFilters tuned_filters() const;     // the same, with the mode each stage serves
    PlannerParameters planner_parameters() const;
};

// Built-in machine used when no INI is given: X Y Z at 300 mm/s, 5000 mm/s^2, 100000 mm/s^3,
// 1 ms servo period, every move smoothed at those limits (no T1: not the paper's fixed chain),
// 0.05 mm tolerance, 0.001 mm arc chords.
MachineConfig default_machine();

// Reads the keys above over default_machine(). [TRAJ]LINEAR_UNITS must be mm (or absent): firtp
// plans in mm. Throws ConfigError naming file, line and key for a
// value that is not a number, is out of range (zero, negative, NaN) or a [FIRTP] key it does not know.
MachineConfig load_machine(const IniFile& ini);

// Command-line overrides (--t1 --t2 --tolerance --period), each validated like the INI keys;
// throws ConfigError naming the flag.
struct MachineOverrides {
    std::optional<double> t1, t2, tolerance, period;
};
void apply_overrides(MachineConfig& machine, const MachineOverrides& overrides);

// Structural modes as [FIRTP]MODES and `firtp simulate --modes` write them: words separated by
// blanks or commas, each `HZ`, `HZ/DAMPING` or `L:HZ[/DAMPING]` with L an axis letter (the mode
// moves that axis only; without it, every axis). Damping defaults to default_mode_damping.
// `axes` is the machine's axis count. Throws ConfigError with the reason (no file name).
std::vector<StructuralMode> parse_modes(std::string_view text, int axes);

// [FIRTP]ROBUST / --robust: `none`, `double`, `straddle` or `straddle SPREAD` (also `straddle:SPREAD`,
// 0 < SPREAD < 0.5). Sets tuning.robust and tuning.spread; throws ConfigError with the reason.
void parse_robust(std::string_view text, ModeTuning& tuning);

}  // namespace firtp
