// Each setting's default, stated once. The INI reader (machine.cpp), the CLI, firtp.so and
// firtp_tp take their defaults from here. Where a help text, a module parameter's description or
// a man page shows a default, it shows the FIRTP_DEFAULT_*_TEXT spelling; the number is read from
// that same text at compile time, so the two cannot differ (tests/install/man_pages.sh holds the
// man pages and the GUIDE to these texts).
#pragma once

#include <cstddef>

#define FIRTP_DEFAULT_TOLERANCE_TEXT "0.05"
#define FIRTP_DEFAULT_RATE_RESERVE_TEXT "0.2"
#define FIRTP_DEFAULT_ARC_CHORD_TOLERANCE_TEXT "0.001"
#define FIRTP_DEFAULT_MAX_FEED_OVERRIDE_TEXT "1"
// The modules' load-time settings (loadrt firtp ..., firtp_tp's TPMOD line).
#define FIRTP_DEFAULT_QUEUE_TEXT "1024"
#define FIRTP_DEFAULT_MAX_BLOCKS_TEXT "32"
#define FIRTP_DEFAULT_STREAM_DEPTH_TEXT "4096"
#define FIRTP_DEFAULT_BRAKE_SPEED_TEXT "1"
#define FIRTP_DEFAULT_PLAN_BUDGET_US_TEXT "250"
#define FIRTP_TP_DEFAULT_BLOCKS_TEXT "4096"
#define FIRTP_TP_DEFAULT_MAX_BLOCKS_TEXT "64"

namespace firtp {

// A plain decimal "12.345" as the nearest double (digits / 10^k, both exact: one rounding).
constexpr double decimal_value(const char* text) {
    double digits = 0.0, scale = 1.0;
    bool fraction = false;
    for (; *text != '\0'; ++text) {
        if (*text == '.') {
            fraction = true;
            continue;
        }
        digits = digits * 10.0 + (*text - '0');
        if (fraction) scale *= 10.0;
    }
    return digits / scale;
}

namespace defaults {

// Corner tolerance in machine units for G64 without P (and firtp.so's pin blocks with tolerance 0):
// [FIRTP]TOLERANCE, --tolerance, tolerance=.
inline constexpr double tolerance = decimal_value(FIRTP_DEFAULT_TOLERANCE_TEXT);
// The paper's mode: share of acceleration and jerk kept for the clock's rate ramps (override, hold):
// [FIRTP]RATE_RESERVE, rate_reserve=.
inline constexpr double rate_reserve = decimal_value(FIRTP_DEFAULT_RATE_RESERVE_TEXT);
// Largest sagitta of an arc's chords, machine units: [FIRTP]ARC_CHORD_TOLERANCE, chord_tol=.
inline constexpr double arc_chord_tolerance = decimal_value(FIRTP_DEFAULT_ARC_CHORD_TOLERANCE_TEXT);
// Highest feed override the limits hold up to: [DISPLAY]MAX_FEED_OVERRIDE (LinuxCNC's), max_feed_override=.
inline constexpr double max_feed_override = decimal_value(FIRTP_DEFAULT_MAX_FEED_OVERRIDE_TEXT);
// Servo period: [EMCMOT]SERVO_PERIOD, period_ns=, LinuxCNC's usual 1 ms.
inline constexpr long servo_period_ns = 1'000'000;
inline constexpr double servo_period = servo_period_ns / 1e9;  // s
// Blocks a program may expand to (an arc: one a chord) unless [FIRTP]MAX_PROGRAM_BLOCKS says
// otherwise: 10x the 10^6-block programs the benchmarks plan. 120 bytes a block: 1.2 GB (1.8 GB
// peak measured while the vector grew, at 112 bytes a block before Block::dwell).
inline constexpr std::size_t max_program_blocks = 10'000'000;

// firtp.so (and firtp run / serve, which load it): blocks the planner holds (queue=), stream blocks
// planned per period at most (max_blocks=), periods the streams hold (stream_depth=), and the
// feedback speed, units/s, above which a start or enable brakes from it (brake_speed=).
// Both modules plan at least one block a period and more only while plan_budget_us= lasts (a
// quarter of LinuxCNC's usual period: 32 blocks of the paper's chain took 2 ms).
inline constexpr int queue = static_cast<int>(decimal_value(FIRTP_DEFAULT_QUEUE_TEXT));
inline constexpr int max_blocks = static_cast<int>(decimal_value(FIRTP_DEFAULT_MAX_BLOCKS_TEXT));
inline constexpr int stream_depth = static_cast<int>(decimal_value(FIRTP_DEFAULT_STREAM_DEPTH_TEXT));
inline constexpr double brake_speed = decimal_value(FIRTP_DEFAULT_BRAKE_SPEED_TEXT);
inline constexpr int plan_budget_us = static_cast<int>(decimal_value(FIRTP_DEFAULT_PLAN_BUDGET_US_TEXT));
// firtp_tp: moves accepted and not finished (queue=, as firtp.so's), planned blocks not yet
// finished (blocks=), blocks planned per period (max_blocks=).
inline constexpr int tp_blocks = static_cast<int>(decimal_value(FIRTP_TP_DEFAULT_BLOCKS_TEXT));
inline constexpr int tp_max_blocks = static_cast<int>(decimal_value(FIRTP_TP_DEFAULT_MAX_BLOCKS_TEXT));

}  // namespace defaults
}  // namespace firtp
