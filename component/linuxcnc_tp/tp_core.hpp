// firtp as LinuxCNC's trajectory planner, free of LinuxCNC's headers: what the tp.h functions do,
// on the firtp core (its one owner, Planner: planner.hpp). tp_module.cpp maps tp.h onto this class;
// the tests drive it directly.
//
// Principle of operation:
// - A move (tpAddLine, tpAddCircle) is checked and appended to a ring of moves in O(1). Nothing
//   is planned there: LinuxCNC adds at most one move per servo period, from the command handler.
// - Every period (run_cycle, from tpRunCycle) pending moves are planned into the firtp Planner,
//   chord by chord for arcs, while a budget lasts (at least one block, then up to max_blocks and
//   plan_budget_ns), so a long arc is spread over several periods. The planner is causal: the
//   first move starts on the period it is planned in and a late move only shortens its overlap,
//   so motion never waits for a look-ahead to fill and never stalls when moves come slowly.
// - Every block carries its move's sequence number in Block.line, so the Planner's
//   current_line() names the move in motion: its id, state tag, motion type and enables (kept in
//   the move ring) become exec id/tag/type/enables. A move is finished when its last block has
//   retired; depth = moves accepted and not finished, done = depth 0, full = depth within the
//   margin of the ring's capacity (tcqFull).
// - Feed override and hold scale the filters' clock (the tool stays on the path); pause is rate 0;
//   abort stops on the path, then drops everything (done, depth 0); clear drops at once.
// - Filter times and axis limits define the planner. LinuxCNC sends the axis limits after the
//   planner was created, so the planner is rebuilt from them when they change, in a period
//   where nothing moves (the module passes the limits while idle, so that is before a program's
//   first move). The rebuild allocates; in the LinuxCNC module operator new draws from an arena
//   reserved at load (tp_arena.cpp). Limits (or a period) whose filter window would exceed
//   max_window_periods are refused without allocating: the planner built before is kept and
//   moves are refused (window_too_long) until they change.
//
// Real time: every member except the constructor runs in LinuxCNC's servo thread: no
// allocation (except the rebuild, see above), no locks, no I/O, no exceptions, bounded time.
#pragma once

#include <firtp/defaults.hpp>
#include <firtp/parameters.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace firtp::linuxcnc_tp {

constexpr int pose_axes = 9;
using Pose = std::array<double, pose_axes>;  // X Y Z A B C U V W, machine units (mm or in, degrees)
using Vec3 = std::array<double, 3>;

constexpr std::size_t tag_capacity = 512;  // bytes kept per move for LinuxCNC's state_tag_t

// LinuxCNC's TC_TERM_COND_* and EMC_MOTION_TYPE_* values.
enum TermCond : int { term_stop = 0, term_exact = 1, term_parabolic = 2, term_tangent = 3 };
enum MotionTypes : int { motion_traverse = 1, motion_feed = 2, motion_arc = 3, motion_probing = 5,
                         motion_indexrotary = 6 };

struct TpSettings {
    double period = defaults::servo_period;  // s; tpSetCycleTime changes it
    int stages = 2;                    // FIR stages, 1..4
    std::array<double, 4> filter_times{0.0, 0.0, 0.0, 0.0};  // s, 0: T1 = max v/a, T2 = max a/j over the axes
    double jerk = 100000.0;            // units/s^3 on every axis (0: none); LinuxCNC 2.9 has no jerk limits
    Pose axis_jerk{};                  // units/s^3 per axis X..W where > 0 (the INI's), else `jerk`
    double jerk_of(std::size_t axis) const { return axis_jerk[axis] > 0.0 ? axis_jerk[axis] : std::max(jerk, 0.0); }
    double default_tolerance = defaults::tolerance;  // units: G64 without P, and inside arcs in G61/G61.1
    ToleranceMeaning tolerance_meaning = ToleranceMeaning::corner_point;  // what the tolerance bounds
    double chord_tolerance = defaults::arc_chord_tolerance;  // units: largest sagitta of an arc's chords
    double rate_reserve = defaults::rate_reserve;  // share of acceleration and jerk kept for override/hold ramps (0..1)
    std::size_t moves = defaults::queue;  // moves accepted and not finished, at most
    std::size_t full_margin = 16;      // full() this many moves before the ring is
    std::size_t blocks = defaults::tp_blocks;  // planned blocks not yet retired (the Planner), at most
    int max_blocks_per_cycle = defaults::tp_max_blocks;  // planned per period at most
    std::int64_t plan_budget_ns = defaults::plan_budget_us * 1000;  // and only while planning took less than this (0: no time limit)
    std::int64_t (*clock_ns)() = nullptr;  // monotonic clock for the budget (rtapi_get_time)
    double max_chords = 1.0e6;         // an arc needing more is refused
    // [TASK]CYCLE_TIME, s (0: unknown). While a program streams, LinuxCNC hands moves at most a task
    // cycle or so apart: where none came for three, LinuxCNC waits for motion to end (M3, M5, a lone
    // MDI move), and a start waiting for more moves starts (PlannerParameters::start_idle).
    double task_cycle = 0.0;
};

// What a tpAdd* call carries besides the geometry.
struct MoveRequest {
    Pose end{};
    int motion_type = motion_feed;
    double vel = 0.0;         // units/s along LinuxCNC's length of the move (X Y Z, else U V W, else A B C)
    double ini_maxvel = 0.0;  // the most feed override may reach (not used: see README)
    double acc = 0.0;         // largest acceleration along the move; caps vel at acc * T1 (0: none)
    unsigned char enables = 0;
    bool atspeed = false;     // wait until the spindle is at speed before this move starts
    int indexer_joint = -1;   // locking indexer (refused)
    const void* tag = nullptr;  // state tag, copied (tag_size <= tag_capacity)
    std::size_t tag_size = 0;
};

struct ArcGeometry {
    Vec3 center{};
    Vec3 normal{};
    int turn = 0;  // LinuxCNC: 0 counter-clockwise about normal, -1 clockwise; |turn| more: full turns
};

enum class AddStatus : int {
    ok = 0,
    zero_length = 1,  // > 0: LinuxCNC ignores it
    aborting = -1,
    not_finite = -2,
    bad_feed = -3,
    queue_full = -4,
    spindle_sync = -5,
    indexer = -6,
    bad_arc = -7,
    too_many_chords = -8,
    no_filters = -9,
    window_too_long = -10,
};
const char* describe(AddStatus status);

struct CycleInputs {
    double feed_scale = 1.0;      // emcmotStatus->net_feed_scale (override, adaptive feed, hold)
    double max_feed_scale = 1.0;  // emcmotConfig->maxFeedScale
    bool spindle_at_speed = true; // every spindle at speed (for atspeed moves)
};

struct OutputWriters {
    void (*digital)(int index, char on) = nullptr;
    void (*analog)(int index, double value) = nullptr;
};

struct CycleStats {
    int planned = 0;              // blocks planned this period
    std::int64_t plan_ns = 0;     // time spent planning (when a clock is set)
    std::int64_t rebuilds = 0;    // planner rebuilds so far
    std::int64_t refused_blocks = 0;  // blocks the planner refused (the program stopped on the path)
    std::int64_t refused_windows = 0; // limit or period changes refused: filter window too long
    std::size_t pending = 0;      // moves not yet completely planned
    std::size_t blocks = 0;       // blocks in the Planner
};

class TpCore {
public:
    // Init only (allocates). Throws std::invalid_argument for settings that cannot work.
    explicit TpCore(const TpSettings& settings);
    ~TpCore();
    TpCore(const TpCore&) = delete;
    TpCore& operator=(const TpCore&) = delete;

    // Configuration; takes effect when nothing moves.
    bool set_period(double seconds);
    void set_axis_limits(const Pose& max_velocity, const Pose& max_acceleration);
    void set_velocity_limit(double limit);  // tool-tip speed cap for moves with linear motion, 0: none
    void set_output_writers(const OutputWriters& writers);

    // State latched for the moves added after it.
    void set_id(int id);
    bool set_term_cond(int cond, double tolerance);
    void set_spindle_sync(double units_per_rev);  // 0: not synchronised
    bool latch_digital(int index, bool on);       // applied when the next added move starts
    bool latch_analog(int index, double value);

    AddStatus add_line(const MoveRequest& move);
    AddStatus add_arc(const MoveRequest& move, const ArcGeometry& arc);

    void pause();
    void resume();
    void abort();                      // stop on the path, then drop everything
    void clear();                      // drop everything now, keep the position; G64, no sync (as tpClear)
    void set_position(const Pose& p);  // position and goal; drops everything

    void run_cycle(const CycleInputs& in);  // one trajectory period

    // Status after the last run_cycle (or change).
    const Pose& position() const;
    bool done() const;
    int depth() const;          // moves accepted and not finished
    int active_depth() const;   // moves in motion at once
    bool full() const;
    bool aborting() const;
    bool has_exec() const;      // a move is executing (or next to)
    int exec_id() const;        // its id (0 when none)
    int motion_type() const;    // its EMC_MOTION_TYPE (0 when none)
    unsigned char exec_enables() const;
    const void* exec_tag() const;  // tag bytes of the executing move (nullptr when none)
    double current_vel() const;    // path speed now (X Y Z, else U V W, else A B C)
    double requested_vel() const;  // vel of the executing move
    double distance_to_go() const; // straight distance to its end
    Pose dtg() const;              // its end minus the position, per axis
    const CycleStats& stats() const;
    // Whether the filters the settings, limits and period ask for now can be built: ok, no_filters
    // or window_too_long (moves are then refused with it); and their delay T1 + ... + Tn in s.
    AddStatus filter_status() const;
    double filter_delay() const;
    const TpSettings& settings() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace firtp::linuxcnc_tp
