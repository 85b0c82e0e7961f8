// Settings of the FIR chain and the planner (Sencer et al. 2015).
#pragma once

#include <firtp/defaults.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace firtp {

constexpr int max_stages = 4;

// Moving-average time constants T1 >= T2 >= ... (Eq. 1-2), seconds.
struct FilterTimes {
    int stages = 2;
    std::array<double, max_stages> T{0.0, 0.0, 0.0, 0.0};

    double delay() const;  // Td = T1 + ... + Tn (Eq. 6)
};

// What the tolerance epsilon bounds at a corner.
enum class ToleranceMeaning {
    corner_point,  // closest approach of the tool to the programmed corner point (the paper's)
    contour,       // largest distance from the programmed path
};

// The words INI files, the CLI and the modules use: "corner" or "contour" (exactly); nullopt otherwise.
std::optional<ToleranceMeaning> parse_tolerance_meaning(std::string_view word);
const char* to_string(ToleranceMeaning meaning);

struct AxisLimits {
    double max_velocity = 0.0;      // units/s
    double max_acceleration = 0.0;  // units/s^2
    double max_jerk = 0.0;          // units/s^3, 0 = not limited
};

// Machine limits per axis (only the first `axes` entries are used).
struct MachineLimits {
    int axes = 3;
    std::array<AxisLimits, 9> axis{};
    double max_linear_velocity = 0.0;  // [TRAJ]MAX_LINEAR_VELOCITY, 0 = not limited
};

struct PlannerParameters {
    // The paper's mode: `filters` smooth every block, corners overlap by Tk (paper_planner.hpp).
    // Otherwise every velocity change is smoothed at the limits (kernel.hpp, lookahead.hpp) and
    // `filters` is not used.
    bool fixed_chain = false;
    FilterTimes filters;
    double period = defaults::servo_period;  // servo period, s
    ToleranceMeaning tolerance_meaning = ToleranceMeaning::corner_point;
    double fixed_overlap = -1.0;        // Tk forced at every blended corner (s); < 0: from the tolerance
    std::size_t queue_capacity = 256;   // blocks the interpolator holds at once
    MachineLimits limits;               // held at every sample, overlaps included (0 = not limited)
    double max_rate = defaults::max_feed_override;  // highest feed override (MAX_FEED_OVERRIDE): limits hold up to it
    double rate_reserve = defaults::rate_reserve;  // the paper's mode: share of a and j kept for its clock's rate ramps
    // From rest, the first step waits at most this long (s) for the look-ahead to settle it, and
    // (start_idle > 0) no longer than start_idle after the last block came: a caller that hands
    // blocks as they come knows how long a pause in them means none follow for now.
    double start_wait = 0.05;
    double start_idle = 0.0;
};

// What a plan at rate 1 may use. The paper's mode scales its clock for the override, so any rate
// up to max_rate M, ramped within rate_limits() (time_scale.hpp), must keep `limits`: v / M,
// a (1 - r) / M^2, j (1 - r) / M^3 (r = rate_reserve); time scaling leaves the path alone, so
// corner errors do not depend on the rate. Smoothing at the limits plans every rate as its own
// motion: the limits themselves.
MachineLimits planned_limits(const PlannerParameters& parameters);

// The paper's fixed chain pulls a circle of radius R inwards by about v^2 sum(T_i^2) / (24 R): the
// highest arc speed that keeps this within 90 % of `tolerance` (the rest is for the chords and the
// junctions: with all of it the planner has no room and the feed goes stop-and-go). +inf without
// a tolerance. Smoothing at the limits needs no cap: it checks every chord's corner.
double arc_speed_limit(const FilterTimes& filters, double radius, double tolerance);

// An axis' jerk limit from the INI keys of LinuxCNC master's jerk-limited planner: its
// [AXIS_L]MAX_JERK (`own`, 0: not set), a linear axis (not A, B, C) at most
// [TRAJ]MAX_LINEAR_JERK (`linear`, 0: not set); 0 where neither applies. firtp and firtp_tp read it so.
double ini_axis_jerk(char letter, double own, double linear);

// T2's default for the paper's chain (Eq. 4: j = a / T2): max over the axes of A_a / J_a; 0 when
// no axis limits jerk. Smoothing at the limits: jerk_time(smoothing_limits(limits)).
double jerk_time(const MachineLimits& limits);

// The limits smoothing at the limits plans with: the widest jerk time
// T2 = max_a min(A_a / J_a, sqrt(2 V_a / J_a)) (a step's own is over the axes moving in it:
// lookahead.hpp, Regime), and the acceleration of axis a is capped at min(A_a, J_a T2). A step of dV on an axis reaches at most sqrt(J_a dV) (dV <= 2 V_a, a reversal),
// and for every such step this T2 gives a kernel no wider than T2 = A_a / J_a does: planned at a
// higher A_a, T2 would grow for every step, and more acceleration would make the machine slower
// (tests/bench/cliffs.cpp). Lower accelerations only, so every guarantee against `limits` holds.
MachineLimits smoothing_limits(const MachineLimits& limits);

// Smoothing at the limits: a hold or an abort brings the axes to rest within this time (s). The
// step under way ends (at most one full-speed step, V_a / A_a + T2 on its most loaded axis, with
// smoothing_limits' A_a and T2), then one more step from the highest speed to rest; a dense run
// (runs of short blocks) may use twice the jerk time. Measured by tests/core/limits_override_test.cpp.
double hold_time_bound(const PlannerParameters& parameters);

// Checks max_rate >= 1 and 0 < rate_reserve < 1, finite; returns an empty string or the reason.
const char* validate_rate(const PlannerParameters& parameters);

// T1 from velocity/acceleration, T2 from acceleration/jerk (Eq. 4: a = v / T1, j = a / T2).
// Explicit times (> 0 in `given`) win over derived ones. With mode frequencies, the times are
// tuned to them (Eq. 10, T = k / f) at the smallest delay, the times above as lower bounds
// (tune_filter_times in mode_tuning.hpp, damping default_mode_damping). Throws
// std::invalid_argument when a stage can be neither given nor derived.
FilterTimes filter_times_from_limits(const MachineLimits& limits, int stages,
                                     std::span<const double> given,
                                     std::span<const double> mode_frequencies_hz);

// The times above by position, untuned: given T_i, else T1 = max v/a and T2 = max a/j over the
// axes; 0 where neither.
std::array<double, max_stages> limit_filter_times(const MachineLimits& limits, std::span<const double> given);

// Checks T1 >= ... >= Tn > 0, 1 <= n <= 4, finite; returns an empty string or the reason.
const char* validate(const FilterTimes& filters);

// The longest filter delay a planner is built for, in servo periods: the planner keeps the samples
// of one filter window (Td / period of them), so its memory and the time to plan a block grow
// with it. 20,000 periods are 20 s at 1 ms (the paper's machine needs 237).
constexpr double max_window_periods = 20000.0;

// Checks a positive, finite period and Td / period <= max_window_periods; returns an empty string
// or the reason.
const char* validate_window(const FilterTimes& filters, double period);

}  // namespace firtp
