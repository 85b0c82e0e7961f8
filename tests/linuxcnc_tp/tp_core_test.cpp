// firtp_tp's logic without LinuxCNC: moves go in as motmod's command handler adds them (at most
// one a period), tpRunCycle's work runs every period, and the trajectory is measured: tolerance,
// axis limits, end point, the done/depth handshake, exec ids, override, hold, abort, clear,
// refusals, outputs, budget, and no allocation in the servo-thread calls.
#include <tp_core.hpp>

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <numbers>
#include <string>
#include <vector>

#include "allocation_counter.hpp"

namespace {

using namespace firtp::linuxcnc_tp;
using firtp::AxisState;
using firtp::AxisVector;

Pose pose(double x, double y, double z = 0.0) {
    Pose p{};
    p[0] = x, p[1] = y, p[2] = z;
    return p;
}

AxisVector vec(const Pose& p) {
    AxisVector v;
    for (int i = 0; i < 9; ++i) v[i] = p[static_cast<std::size_t>(i)];
    return v;
}

// The diamond's machine: X Y at 300 mm/s, 5000 mm/s^2; the paper's filters.
TpSettings diamond_settings() {
    TpSettings s;
    s.filter_times = {0.148, 0.089, 0.0, 0.0};
    s.jerk = 0.0;
    s.default_tolerance = 0.5;
    s.clock_ns = [] {
        return static_cast<std::int64_t>(
            std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
                .count());
    };
    return s;
}

// Smoothing at the machine's limits (no fixed chain), jerk 1e5 on every axis.
TpSettings limits_settings() {
    TpSettings s = diamond_settings();
    s.filter_times = {0.0, 0.0, 0.0, 0.0};
    s.jerk = 100000.0;
    return s;
}

Pose limits(double value, int axes = 3) {
    Pose p{};
    for (int i = 0; i < axes; ++i) p[static_cast<std::size_t>(i)] = value;
    return p;
}

struct Add {
    bool arc = false;
    MoveRequest move;
    ArcGeometry geometry;
    int cond = term_parabolic;
    double tolerance = 0.0;
};

// motmod's servo thread: the command handler adds at most one move a period (when the queue is
// not full), then the controller runs one cycle; every period's position is recorded.
struct Machine {
    TpCore tp;
    std::deque<Add> program;
    std::vector<AxisState> samples;
    std::vector<int> exec_ids, depths, done;
    std::vector<AddStatus> results;
    CycleInputs in;
    int period_count = 0;
    int every = 1;  // a move every `every` periods

    explicit Machine(const TpSettings& s, double v = 300.0, double a = 5000.0) : tp(s) {
        tp.set_axis_limits(limits(v), limits(a));
        tp.set_position(pose(0, 0));
    }

    void line(const Pose& end, double vel, int id, int cond = term_parabolic, double tolerance = 0.0,
              int type = motion_feed) {
        Add a;
        a.move.end = end;
        a.move.vel = vel;
        a.move.motion_type = type;
        a.move.acc = 1e9;
        a.cond = cond;
        a.tolerance = tolerance;
        program.push_back(a);
        program.back().move.tag = nullptr;
        ids.push_back(id);
    }
    void arc(const Pose& end, const Vec3& center, const Vec3& normal, int turn, double vel, int id,
             double tolerance) {
        Add a;
        a.arc = true;
        a.move.end = end;
        a.move.vel = vel;
        a.move.motion_type = motion_arc;
        a.geometry = {center, normal, turn};
        a.tolerance = tolerance;
        program.push_back(a);
        ids.push_back(id);
    }

    void cycle() {
        if (!program.empty() && !tp.full() && period_count % every == 0) {
            const Add& a = program.front();
            tp.set_term_cond(a.cond, a.tolerance);
            tp.set_id(ids[next_id++]);
            results.push_back(a.arc ? tp.add_arc(a.move, a.geometry) : tp.add_line(a.move));
            program.pop_front();
        }
        tp.run_cycle(in);
        AxisState s;
        s.time = period_count * 0.001;
        s.position = vec(tp.position());
        samples.push_back(s);
        exec_ids.push_back(tp.exec_id());
        depths.push_back(tp.depth());
        done.push_back(tp.done() ? 1 : 0);
        ++period_count;
    }

    // Until the program is in and motion is done; false if that takes longer than `limit` periods.
    bool run(int limit = 100000) {
        for (int i = 0; i < limit; ++i) {
            cycle();
            if (program.empty() && tp.done()) return true;
        }
        return false;
    }

    std::vector<int> ids;
    std::size_t next_id = 0;
};

std::vector<AxisVector> diamond_points() {
    return {vec(pose(0, 0)), vec(pose(25, 25)), vec(pose(50, 0)), vec(pose(25, -25)), vec(pose(0, 0))};
}

void add_diamond(Machine& m, double tolerance = 0.5) {
    const auto points = diamond_points();
    for (std::size_t k = 1; k < points.size(); ++k) {
        Pose p{};
        for (int i = 0; i < 9; ++i) p[static_cast<std::size_t>(i)] = points[k][i];
        m.line(p, 250.0, static_cast<int>(k + 4), term_parabolic, tolerance);
    }
}

// The motion from the first moving sample to the first sample at rest at the end.
std::vector<AxisState> motion(const std::vector<AxisState>& samples) {
    std::size_t first = 0;
    while (first + 1 < samples.size() && samples[first + 1].position == samples[first].position) ++first;
    std::size_t last = samples.size() - 1;
    while (last > first && samples[last - 1].position == samples[last].position) --last;
    std::vector<AxisState> out(samples.begin() + static_cast<long>(first), samples.begin() + static_cast<long>(last) + 1);
    for (std::size_t k = 0; k < out.size(); ++k) out[k].time = static_cast<double>(k) * 0.001;
    return out;
}

TEST(TpCore, DiamondOneMoveAPeriodEqualsTheOfflinePlanWithinToleranceAndLimits) {
    Machine m(diamond_settings());
    m.in.max_feed_scale = 1.0;
    add_diamond(m);
    ASSERT_TRUE(m.run());
    for (AddStatus r : m.results) EXPECT_EQ(r, AddStatus::ok);
    const auto moving = motion(m.samples);
    const firtp::Measured measured = firtp::measure(moving, diamond_points(), 0.001);
    EXPECT_LE(measured.max_corner_error, 0.5 + 1e-9);
    EXPECT_GT(measured.max_corner_error, 0.45);  // the tolerance is used, not wasted
    EXPECT_EQ((measured.end_position - vec(pose(0, 0))).norm(), 0.0);
    for (int a = 0; a < 2; ++a) {
        EXPECT_LE(measured.max_velocity[a], 300.0 * (1 + 1e-9));
        EXPECT_LE(measured.max_acceleration[a], 5000.0 * 0.8 * (1 + 1e-6));
    }
    // The same planner offline, every block available at once: the same samples.
    firtp::PlannerParameters p;
    p.fixed_chain = true;
    p.filters.stages = 2;
    p.filters.T = {0.148, 0.089, 0.0, 0.0};
    p.limits.axes = 9;
    for (int a = 0; a < 3; ++a) p.limits.axis[a] = {300.0, 5000.0, 0.0};
    p.queue_capacity = 64;
    std::vector<firtp::Block> blocks;
    for (std::size_t k = 1; k < diamond_points().size(); ++k) {
        firtp::Block b;
        b.target = diamond_points()[k];
        b.feed = 250.0;
        b.tolerance = 0.5;
        blocks.push_back(b);
    }
    const firtp::Trajectory offline = firtp::plan_trajectory(p, vec(pose(0, 0)), blocks);
    const auto reference = motion(offline.samples);
    ASSERT_EQ(moving.size(), reference.size());
    double largest = 0.0;
    for (std::size_t k = 0; k < moving.size(); ++k)
        largest = std::max(largest, (moving[k].position - reference[k].position).norm());
    EXPECT_LE(largest, 1e-9);
    EXPECT_NEAR(measured.cycle_time, 1.225, 0.002);
}

TEST(TpCore, DoneAndDepthZeroExactlyWhenMotionEnds) {
    Machine m(diamond_settings());
    add_diamond(m);
    ASSERT_TRUE(m.run());
    // Motion starts on the period the first move is added; depth counts moves not finished.
    EXPECT_EQ(m.depths[0], 1);
    EXPECT_NE(m.samples[1].position, m.samples[0].position);
    std::size_t last_motion = 0;
    for (std::size_t k = 1; k < m.samples.size(); ++k)
        if (m.samples[k].position != m.samples[k - 1].position) last_motion = k;
    for (std::size_t k = 0; k < m.samples.size(); ++k) {
        if (k < last_motion) {
            EXPECT_EQ(m.done[k], 0) << k;
            EXPECT_GT(m.depths[k], 0) << k;
        }
    }
    EXPECT_EQ(m.done.back(), 1);
    EXPECT_EQ(m.depths.back(), 0);
    EXPECT_EQ(m.tp.exec_id(), 0);
    EXPECT_EQ(m.tp.motion_type(), 0);
    // Finished on the sample where the tool came to rest on the end point, not later.
    EXPECT_LE(m.samples.size() - 1, last_motion + 1);
    EXPECT_EQ(m.samples.back().position, vec(pose(0, 0)));
}

TEST(TpCore, ExecIdFollowsTheMovesInOrder) {
    Machine m(diamond_settings());
    add_diamond(m);
    ASSERT_TRUE(m.run());
    std::vector<int> seen;
    for (int id : m.exec_ids)
        if (id != 0 && (seen.empty() || seen.back() != id)) seen.push_back(id);
    EXPECT_EQ(seen, (std::vector<int>{5, 6, 7, 8}));
}

TEST(TpCore, ExecTagTypeAndEnablesComeFromTheExecutingMove) {
    TpCore tp(diamond_settings());
    tp.set_axis_limits(limits(300), limits(5000));
    const char tag_a[] = "first", tag_b[] = "second";
    MoveRequest r;
    r.end = pose(10, 0);
    r.vel = 100;
    r.motion_type = motion_traverse;
    r.enables = 0x3;
    r.tag = tag_a;
    r.tag_size = sizeof tag_a;
    tp.set_id(11);
    ASSERT_EQ(tp.add_line(r), AddStatus::ok);
    r.end = pose(10, 10);
    r.motion_type = motion_feed;
    r.enables = 0x5;
    r.tag = tag_b;
    r.tag_size = sizeof tag_b;
    tp.set_id(12);
    ASSERT_EQ(tp.add_line(r), AddStatus::ok);
    CycleInputs in;
    tp.run_cycle(in);
    ASSERT_TRUE(tp.has_exec());
    EXPECT_EQ(tp.exec_id(), 11);
    EXPECT_EQ(tp.motion_type(), motion_traverse);
    EXPECT_EQ(tp.exec_enables(), 0x3);
    EXPECT_STREQ(static_cast<const char*>(tp.exec_tag()), "first");
    EXPECT_DOUBLE_EQ(tp.requested_vel(), 100.0);
    int guard = 0;
    while (tp.exec_id() == 11 && ++guard < 10000) tp.run_cycle(in);
    EXPECT_EQ(tp.exec_id(), 12);
    EXPECT_EQ(tp.motion_type(), motion_feed);
    EXPECT_EQ(tp.exec_enables(), 0x5);
    EXPECT_STREQ(static_cast<const char*>(tp.exec_tag()), "second");
    EXPECT_GT(tp.current_vel(), 0.0);
    const Pose d = tp.dtg();
    EXPECT_NEAR(d[1], 10.0 - tp.position()[1], 1e-12);
    EXPECT_NEAR(tp.distance_to_go(), std::hypot(d[0], d[1]), 1e-12);
}

// Exact stop (G61): the tool rests on the corner point, sampled there.
TEST(TpCore, ExactStopRestsOnTheCorner) {
    Machine m(diamond_settings());
    m.line(pose(20, 0), 200, 1, term_exact);
    m.line(pose(20, 20), 200, 2, term_exact);
    ASSERT_TRUE(m.run());
    const auto corner = vec(pose(20, 0));
    const bool visited = std::any_of(m.samples.begin(), m.samples.end(),
                                     [&](const AxisState& s) { return s.position == corner; });
    EXPECT_TRUE(visited);
    const firtp::Measured measured =
        firtp::measure(motion(m.samples), std::vector<AxisVector>{vec(pose(0, 0)), corner, vec(pose(20, 20))}, 0.001);
    EXPECT_LE(measured.max_contour_error, 1e-12);
}

// G64 without P: the module's default tolerance.
TEST(TpCore, PlainG64UsesTheDefaultTolerance) {
    TpSettings s = diamond_settings();
    s.default_tolerance = 0.1;
    Machine m(s);
    add_diamond(m, 0.0);
    ASSERT_TRUE(m.run());
    const firtp::Measured measured = firtp::measure(motion(m.samples), diamond_points(), 0.001);
    EXPECT_LE(measured.max_corner_error, 0.1 + 1e-9);
    EXPECT_GT(measured.max_corner_error, 0.08);
}

// A circle and a helix, both directions: every sample within the tolerance of the true arc.
struct ArcCase {
    int turn;
    double z_end;
};
class TpArc : public ::testing::TestWithParam<ArcCase> {};

TEST_P(TpArc, SamplesStayOnTheArcWithinTolerance) {
    const ArcCase c = GetParam();
    TpSettings s = diamond_settings();
    s.filter_times = {0.06, 0.05, 0.0, 0.0};
    Machine m(s);
    const double tolerance = 0.02, radius = 20.0;
    m.tp.set_position(pose(20, 0, 0));
    m.arc(pose(20, 0, c.z_end), {0, 0, 0}, {0, 0, 1}, c.turn, 250.0, 1, tolerance);
    ASSERT_TRUE(m.run());
    ASSERT_EQ(m.results[0], AddStatus::ok);
    const auto moving = motion(m.samples);
    const int turns = c.turn < 0 ? -c.turn : c.turn + 1;
    double worst = 0.0, swept = 0.0, previous = 0.0;
    for (std::size_t k = 0; k < moving.size(); ++k) {
        const AxisVector& p = moving[k].position;
        worst = std::max(worst, std::abs(std::hypot(p[0], p[1]) - radius));
        const double angle = std::atan2(p[1], p[0]);
        if (k > 0) {
            double d = angle - previous;
            if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
            if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
            swept += d;
            // The helix rises with the angle.
            EXPECT_NEAR(p[2], c.z_end * std::abs(swept) / (2 * std::numbers::pi * turns), 0.05);
        }
        previous = angle;
    }
    EXPECT_LE(worst, tolerance + 0.001 + 1e-9);  // the tolerance from the chords, plus their sagitta
    const double direction = c.turn < 0 ? -1.0 : 1.0;
    EXPECT_NEAR(swept, direction * 2 * std::numbers::pi * turns, 1e-6);
    EXPECT_EQ(moving.back().position, vec(pose(20, 0, c.z_end)));
    // The feed cap sqrt(24 R tol / sum T^2) lets the circle keep a steady speed.
    const double cap = std::sqrt(24.0 * radius * 0.9 * tolerance / (0.06 * 0.06 + 0.05 * 0.05));
    const double helix = std::hypot(2 * std::numbers::pi * radius * turns, c.z_end);
    const double seconds = static_cast<double>(moving.size()) * 0.001;
    EXPECT_LE(seconds, helix / cap + 0.11 + 0.02);  // at the cap from start to end, plus the filters' delay
    std::printf("arc turn %d: %.3f s, %.3f s at the cap\n", c.turn, seconds, helix / cap);
}

INSTANTIATE_TEST_SUITE_P(Arcs, TpArc,
                         ::testing::Values(ArcCase{0, 0.0}, ArcCase{-1, 0.0}, ArcCase{0, -5.0}, ArcCase{-2, 3.0}));

// A quarter arc in X Y ends exactly where asked, counter-clockwise by default.
TEST(TpCore, QuarterArcGoesCounterClockwiseAndEndsExactly) {
    Machine m(diamond_settings());
    m.tp.set_position(pose(10, 0));
    m.arc(pose(0, 10), {0, 0, 0}, {0, 0, 1}, 0, 100.0, 1, 0.05);
    ASSERT_TRUE(m.run());
    const auto moving = motion(m.samples);
    for (const AxisState& s : moving) EXPECT_GE(s.position[0] + s.position[1], 10.0 - 0.06);  // never across the centre
    EXPECT_EQ(moving.back().position, vec(pose(0, 10)));
}

// A long arc is planned over many periods within the budget; motion starts at once and never stalls.
TEST(TpCore, LongArcIsSpreadOverPeriodsAndMotionNeverStalls) {
    TpSettings s = diamond_settings();
    s.filter_times = {0.06, 0.05, 0.0, 0.0};
    s.max_blocks_per_cycle = 4;
    s.chord_tolerance = 0.0005;
    Machine m(s);
    m.tp.set_position(pose(50, 0));
    m.arc(pose(50, 0), {0, 0, 0}, {0, 0, 1}, 1, 250.0, 1, 0.05);  // two turns, about 3500 chords
    int most = 0;
    bool started = false;
    std::size_t stalls = 0;
    for (int k = 0; k < 100000; ++k) {
        m.cycle();
        most = std::max(most, m.tp.stats().planned);
        const std::size_t n = m.samples.size();
        if (n >= 2) {
            const bool moved = m.samples[n - 1].position != m.samples[n - 2].position;
            if (moved) started = true;
            else if (started && !m.tp.done()) ++stalls;
        }
        if (m.program.empty() && m.tp.done()) break;
    }
    EXPECT_TRUE(m.tp.done());
    EXPECT_LE(most, 4);
    EXPECT_EQ(stalls, 0u);
    EXPECT_TRUE(m.samples[1].position != m.samples[0].position);
}

// Short moves arriving one a period (as LinuxCNC delivers them): the tool keeps moving.
TEST(TpCore, DenseMovesOneAPeriodKeepTheToolMoving) {
    TpSettings s = diamond_settings();
    s.filter_times = {0.06, 0.05, 0.0, 0.0};
    Machine m(s);
    std::vector<AxisVector> points{vec(pose(0, 0))};
    for (int k = 1; k <= 600; ++k) {  // a gentle wave of 0.5 mm steps at 100 mm/s: 5 ms each
        const Pose p = pose(0.5 * k, 0.5 * std::sin(0.5 * k / 20.0));
        m.line(p, 100.0, k, term_parabolic, 0.01);
        points.push_back(vec(p));
    }
    ASSERT_TRUE(m.run());
    const auto moving = motion(m.samples);
    std::size_t stopped = 0;
    for (std::size_t k = 1; k + 1 < moving.size(); ++k)
        if (moving[k].position == moving[k - 1].position) ++stopped;
    EXPECT_EQ(stopped, 0u);
    const firtp::Measured measured = firtp::measure(moving, points, 0.001);
    EXPECT_LE(measured.max_contour_error, 0.01 + 1e-9);
    double length = 0.0;
    for (std::size_t k = 1; k < points.size(); ++k) length += (points[k] - points[k - 1]).norm();
    EXPECT_GT(length / measured.cycle_time, 0.8 * 100.0);  // average speed
    for (int a = 0; a < 2; ++a) EXPECT_LE(measured.max_acceleration[a], 5000.0 * (1 + 1e-6));
}

// Feed override scales the clock: same path, longer time; above 100 % up to the maximum.
TEST(TpCore, FeedOverrideKeepsThePathAndScalesTime) {
    double times[2];
    double errors[2];
    const double scales[2] = {0.5, 1.0};
    for (int i = 0; i < 2; ++i) {
        Machine m(diamond_settings());
        m.in.feed_scale = scales[i];
        add_diamond(m);
        ASSERT_TRUE(m.run());
        const firtp::Measured measured = firtp::measure(motion(m.samples), diamond_points(), 0.001);
        times[i] = measured.cycle_time;
        errors[i] = measured.max_corner_error;
        for (int a = 0; a < 2; ++a) EXPECT_LE(measured.max_acceleration[a], 5000.0 * (1 + 1e-6));
    }
    EXPECT_NEAR(times[0], 2.0 * times[1], 0.002);
    // The same path, sampled twice as densely in the filters' time: the corner error seen on the
    // samples differs a little, both within the tolerance.
    EXPECT_NEAR(errors[0], errors[1], 1e-3);
    EXPECT_LE(std::max(errors[0], errors[1]), 0.5 + 1e-9);
}

TEST(TpCore, OverrideIsCappedAtTheMaximumAndKeepsTheLimits) {
    firtp::Measured measured[2];
    for (int i = 0; i < 2; ++i) {
        Machine m(diamond_settings());
        m.in.feed_scale = i == 0 ? 1.0 : 5.0;
        m.in.max_feed_scale = 1.5;
        add_diamond(m);
        ASSERT_TRUE(m.run());
        measured[i] = firtp::measure(motion(m.samples), diamond_points(), 0.001);
        for (int a = 0; a < 2; ++a) {
            EXPECT_LE(measured[i].max_velocity[a], 300.0 * (1 + 1e-9));
            EXPECT_LE(measured[i].max_acceleration[a], 5000.0 * (1 + 1e-6));
        }
        // At 150 % the samples are 1.5 filter periods apart, not the grid the corners were checked
        // on: a chord lies within its sagitta |a| T^2 / 8 of the path (as RateLimits holds them).
        const double sagitta = i == 0 ? 1e-9 : std::sqrt(2.0) * 5000.0 * 0.001 * 0.001 / 8;
        EXPECT_LE(measured[i].max_corner_error, 0.5 + sagitta);
    }
    EXPECT_NEAR(measured[1].max_path_speed / measured[0].max_path_speed, 1.5, 0.01);
    EXPECT_NEAR(measured[0].cycle_time / measured[1].cycle_time, 1.5, 0.01);
}

// Pause holds on the path; resume finishes the program.
TEST(TpCore, PauseHoldsOnThePathAndResumeFinishes) {
    Machine m(diamond_settings());
    add_diamond(m);
    for (int k = 0; k < 300; ++k) m.cycle();
    m.tp.pause();
    for (int k = 0; k < 600; ++k) m.cycle();
    const AxisVector held = m.samples.back().position;
    for (int k = 0; k < 100; ++k) m.cycle();
    EXPECT_EQ(m.samples.back().position, held);
    EXPECT_FALSE(m.tp.done());
    m.tp.resume();
    ASSERT_TRUE(m.run());
    const firtp::Measured measured = firtp::measure(motion(m.samples), diamond_points(), 0.001);
    EXPECT_LE(measured.max_corner_error, 0.5 + 1e-9);
    EXPECT_EQ(m.samples.back().position, vec(pose(0, 0)));
}

// Abort: stop on the path, then everything is dropped; adds are refused until then.
TEST(TpCore, AbortStopsOnThePathThenFlushes) {
    Machine m(diamond_settings());
    add_diamond(m);
    for (int k = 0; k < 200; ++k) m.cycle();
    ASSERT_FALSE(m.tp.done());
    m.tp.abort();
    MoveRequest r;
    r.end = pose(1, 1);
    r.vel = 10;
    EXPECT_EQ(m.tp.add_line(r), AddStatus::aborting);
    m.program.clear();
    int periods = 0;
    while (!m.tp.done() && periods < 5000) m.cycle(), ++periods;
    EXPECT_TRUE(m.tp.done());
    EXPECT_EQ(m.tp.depth(), 0);
    EXPECT_FALSE(m.tp.aborting());
    EXPECT_LT(periods, 1000);  // the ramp to rest is bounded
    // At rest where it stopped, on the path.
    const AxisVector rest = m.samples.back().position;
    for (int k = 0; k < 10; ++k) m.cycle();
    EXPECT_EQ(m.samples.back().position, rest);
    const firtp::Measured measured = firtp::measure(motion(m.samples), diamond_points(), 0.001);
    EXPECT_LE(measured.max_contour_error, 0.5);
    // The next move starts from there.
    r.end = pose(rest[0], rest[1] + 5);
    ASSERT_EQ(m.tp.add_line(r), AddStatus::ok);
    for (int k = 0; k < 2000 && !m.tp.done(); ++k) m.cycle();
    EXPECT_EQ(m.samples.back().position, vec(r.end));
}

TEST(TpCore, ClearDropsEverythingAtOnceAndKeepsThePosition) {
    Machine m(diamond_settings());
    add_diamond(m);
    for (int k = 0; k < 200; ++k) m.cycle();
    const Pose at = m.tp.position();
    m.tp.clear();
    EXPECT_TRUE(m.tp.done());
    EXPECT_EQ(m.tp.depth(), 0);
    EXPECT_EQ(m.tp.position(), at);
    m.program.clear();
    for (int k = 0; k < 10; ++k) m.cycle();
    EXPECT_EQ(m.tp.position(), at);
    EXPECT_EQ(m.tp.current_vel(), 0.0);
}

TEST(TpCore, SetPositionMovesPositionAndGoal) {
    Machine m(diamond_settings());
    m.tp.set_position(pose(5, 5, 1));
    m.line(pose(15, 5, 1), 100, 1);
    ASSERT_TRUE(m.run());
    EXPECT_EQ(m.samples.front().position[0], 5.0);
    EXPECT_EQ(m.samples.back().position, vec(pose(15, 5, 1)));
    for (const AxisState& s : m.samples) EXPECT_NEAR(s.position[1], 5.0, 1e-12);
}

TEST(TpCore, RefusesWhatItCannotDo) {
    TpCore tp(diamond_settings());
    tp.set_axis_limits(limits(300), limits(5000));
    MoveRequest r;
    r.end = pose(1, 0);
    r.vel = 10;
    EXPECT_EQ(tp.add_line(r), AddStatus::ok);
    EXPECT_EQ(tp.add_line(r), AddStatus::zero_length);
    r.end = pose(2, 0);
    r.vel = 0;
    EXPECT_EQ(tp.add_line(r), AddStatus::bad_feed);
    r.vel = 10;
    r.end[4] = std::nan("");
    EXPECT_EQ(tp.add_line(r), AddStatus::not_finite);
    r.end[4] = 0;
    r.indexer_joint = 3;
    EXPECT_EQ(tp.add_line(r), AddStatus::indexer);
    r.indexer_joint = -1;
    tp.set_spindle_sync(1.5);
    EXPECT_EQ(tp.add_line(r), AddStatus::spindle_sync);
    tp.set_spindle_sync(0.0);
    EXPECT_EQ(tp.add_arc(r, {{0, 0, 0}, {0, 0, 0}, 0}), AddStatus::bad_arc);
    EXPECT_EQ(tp.add_line(r), AddStatus::ok);
    EXPECT_FALSE(tp.set_term_cond(7, 0.0));
    for (AddStatus s : {AddStatus::ok, AddStatus::zero_length, AddStatus::aborting, AddStatus::spindle_sync})
        EXPECT_GT(std::string(describe(s)).size(), 5u);
    EXPECT_LT(static_cast<int>(AddStatus::spindle_sync), 0);
    EXPECT_GT(static_cast<int>(AddStatus::zero_length), 0);
}

TEST(TpCore, NoFiltersWithoutLimitsOrTimes) {
    TpSettings s = diamond_settings();
    s.filter_times = {0.0, 0.0, 0.0, 0.0};
    TpCore tp(s);
    MoveRequest r;
    r.end = pose(1, 0);
    r.vel = 10;
    EXPECT_EQ(tp.add_line(r), AddStatus::no_filters);
}

// Without t1 every move is smoothed at the axis limits LinuxCNC sends after creation: a lone
// move starts and stops on the jerk-limited S-curve of its own step (sized_kernel, kernel.hpp).
TEST(TpCore, LimitsSentAfterCreationSmoothEachMoveAtThem) {
    TpSettings s = limits_settings();
    Machine m(s, 300.0, 5000.0);
    m.line(pose(100, 0), 200, 1, term_exact);
    ASSERT_TRUE(m.run());
    EXPECT_EQ(m.tp.stats().rebuilds, 1);  // nothing to build at creation; built at the first move
    EXPECT_EQ(m.tp.filter_delay(), 0.0);  // no fixed chain
    const auto moving = motion(m.samples);
    // The step of 200 mm/s is below a^2 / j = 250 mm/s: T1 = T2 = sqrt(F / j) = 44.7 ms, a
    // triangle of acceleration peaking at sqrt(j F) = 4472 mm/s^2; the move lasts L / F + T1 + T2
    // (the machine's shared jerk stage gave T1 = F / a = 40 ms, T2 = a / j = 50 ms and 4000 mm/s^2).
    const double t = std::sqrt(200.0 / 100000.0);
    EXPECT_NEAR(static_cast<double>(moving.size() - 1) * 0.001, 100.0 / 200.0 + 2.0 * t, 0.002);
    const firtp::Measured measured =
        firtp::measure(moving, std::vector<AxisVector>{vec(pose(0, 0)), vec(pose(100, 0))}, 0.001);
    EXPECT_NEAR(measured.max_acceleration[0], 200.0 / t, 0.02 * 200.0 / t);  // (1 ms differences round the peak)
    EXPECT_LE(measured.max_jerk[0], 100000.0 * (1 + 1e-6));
    EXPECT_GE(measured.max_jerk[0], 100000.0 * 0.95);
}

// Jerk per axis (the INI's [AXIS_L]MAX_JERK, tp_ini.hpp): a slow-jerk Z keeps its limit on a move
// along it and leaves the X Y moves as fast as without it (each step's jerk stage is that of the
// axes moving in it). With one jerk for every axis, the smallest (as before): 2,706 periods against 664.
TEST(TpCore, JerkPerAxisKeepsEachAxisLimitAndLeavesTheOthersMovesAlone) {
    auto run = [](double z_jerk) {
        TpSettings s = limits_settings();
        s.axis_jerk = {100000.0, 100000.0, z_jerk};
        Machine m(s, 300.0, 5000.0);
        m.line(pose(20, 0), 200, 1);
        m.line(pose(20, 20), 200, 2);
        m.line(pose(0, 20), 200, 3);
        m.line(pose(0, 0), 200, 4, term_exact);
        m.line(pose(0, 0, 5), 100, 5, term_exact);
        EXPECT_TRUE(m.run());
        return m.samples;
    };
    const std::vector<AxisState> slow = run(2000.0), fast = run(100000.0);
    const auto square = [](const std::vector<AxisState>& samples) {  // periods until the square ends (Z still at 0)
        std::size_t k = 0;
        while (k < samples.size() && samples[k].position[2] == 0.0) ++k;
        return k;
    };
    std::printf("square: %zu periods with Z's jerk at 2000, %zu at 1e5; whole run %zu / %zu\n", square(slow), square(fast),
                slow.size(), fast.size());
    EXPECT_LE(square(slow), square(fast) + 1);
    const std::vector<AxisVector> points{vec(pose(0, 0)), vec(pose(20, 0)), vec(pose(20, 20)), vec(pose(0, 20)),
                                         vec(pose(0, 0)), vec(pose(0, 0, 5))};
    const firtp::Measured measured = firtp::measure(motion(slow), points, 0.001);
    EXPECT_LE(measured.max_jerk[2], 2000.0 * (1 + 1e-6));
    EXPECT_GE(measured.max_jerk[2], 2000.0 * 0.9);  // Z's own move runs at its own limit
    EXPECT_LE(measured.max_jerk[0], 100000.0 * (1 + 1e-6));
    EXPECT_LE(measured.max_jerk[1], 100000.0 * (1 + 1e-6));
}

// The paper's chain (t1 given, T2 = a / j from the limits): limits whose filter window exceeds
// 20000 periods (validate_window) would make the rebuild allocate for it in the servo thread (2.7
// GB for a window of hours). Refused once, nothing allocated, the planner built before kept (a
// move queued before still ends on it); moves refused until the limits change.
TEST(TpCore, LimitsGivingTooLongAWindowAreRefusedWithoutAllocating) {
    TpSettings s = diamond_settings();
    s.filter_times = {0.06, 0.0, 0.0, 0.0};
    s.jerk = 100000.0;
    TpCore tp(s);
    tp.set_axis_limits(limits(300), limits(5000));  // T1 = 60 ms, T2 = 50 ms
    tp.set_position(pose(0, 0));
    const CycleInputs in;
    MoveRequest r;
    r.vel = 200;
    r.end = pose(10, 0);
    tp.set_term_cond(term_exact, 0.0);
    ASSERT_EQ(tp.add_line(r), AddStatus::ok);
    tp.run_cycle(in);  // built and planned, moving
    ASSERT_EQ(tp.stats().rebuilds, 1);
    ASSERT_FALSE(tp.done());

    const long before = firtp::test::allocation_count();
    tp.set_axis_limits(limits(300), limits(2.5e9));  // T2 = 2.5e9 / 1e5 = 25000 s
    tp.set_axis_limits(limits(300), limits(2.5e9));  // the same again: not counted again
    EXPECT_EQ(tp.filter_status(), AddStatus::window_too_long);
    EXPECT_NEAR(tp.filter_delay(), 25000.0 + 0.06, 1e-9);
    EXPECT_EQ(tp.stats().refused_windows, 1);
    EXPECT_STREQ(describe(AddStatus::window_too_long),
                 "the filter delay T1 + ... + Tn is longer than 20000 servo periods: lower T1 (t1, else "
                 "MAX_VELOCITY / MAX_ACCELERATION) or T2 (t2, else MAX_ACCELERATION / jerk)");
    for (int k = 0; k < 2000 && !tp.done(); ++k) tp.run_cycle(in);
    EXPECT_TRUE(tp.done());
    EXPECT_EQ(tp.position(), pose(10, 0));  // the queued move ended on the planner built before
    r.end = pose(20, 0);
    EXPECT_EQ(tp.add_line(r), AddStatus::window_too_long);
    for (int k = 0; k < 100; ++k) tp.run_cycle(in);
    EXPECT_EQ(tp.stats().rebuilds, 1);
    EXPECT_EQ(tp.position(), pose(10, 0));
    EXPECT_EQ(firtp::test::allocation_count() - before, 0);

    // The previous limits again: rebuilt, moves plan.
    tp.set_axis_limits(limits(300), limits(5000));
    EXPECT_EQ(tp.filter_status(), AddStatus::ok);
    EXPECT_EQ(tp.add_line(r), AddStatus::ok);
    for (int k = 0; k < 2000 && !tp.done(); ++k) tp.run_cycle(in);
    EXPECT_EQ(tp.position(), pose(20, 0));
    EXPECT_EQ(tp.stats().rebuilds, 2);
    EXPECT_EQ(tp.stats().refused_windows, 1);

    // A shorter period makes the same window longer in periods: T2 = 2.5 s is 25000 periods at 0.1 ms.
    tp.set_axis_limits(limits(300), limits(2.5e5));
    EXPECT_EQ(tp.filter_status(), AddStatus::ok);
    ASSERT_TRUE(tp.set_period(0.0001));
    EXPECT_EQ(tp.filter_status(), AddStatus::window_too_long);
    EXPECT_EQ(tp.stats().refused_windows, 2);
}

// The paper's chain with a jerk of 1 (T2 = a / j = 5000 s, 5 million periods): nothing is ever
// built, moves are refused. Smoothing at the limits has no window: the same jerk only makes the
// moves slow.
TEST(TpCore, JerkOfOneIsRefusedBeforeAnyPlannerIsBuilt) {
    TpSettings s = diamond_settings();
    s.filter_times = {0.06, 0.0, 0.0, 0.0};
    s.jerk = 1.0;
    TpCore tp(s);
    const long before = firtp::test::allocation_count();
    tp.set_axis_limits(limits(300), limits(5000));
    EXPECT_EQ(tp.filter_status(), AddStatus::window_too_long);
    EXPECT_EQ(tp.stats().refused_windows, 1);
    MoveRequest r;
    r.vel = 100;
    r.end = pose(1, 0);
    EXPECT_EQ(tp.add_line(r), AddStatus::window_too_long);
    for (int k = 0; k < 10; ++k) tp.run_cycle(CycleInputs{});
    EXPECT_EQ(tp.stats().rebuilds, 0);
    EXPECT_TRUE(tp.done());
    EXPECT_EQ(firtp::test::allocation_count() - before, 0);

    s.filter_times = {0.0, 0.0, 0.0, 0.0};
    TpCore at_limits(s);
    at_limits.set_axis_limits(limits(300), limits(5000));
    EXPECT_EQ(at_limits.filter_status(), AddStatus::ok);
    EXPECT_EQ(at_limits.add_line(r), AddStatus::ok);
}

TEST(TpCore, QueueFullBeforeTheRingIs) {
    TpSettings s = diamond_settings();
    s.moves = 64;
    s.full_margin = 8;
    TpCore tp(s);
    tp.set_axis_limits(limits(300), limits(5000));
    MoveRequest r;
    r.vel = 100;
    int k = 0;
    while (!tp.full()) {
        r.end = pose(++k, 0);
        ASSERT_EQ(tp.add_line(r), AddStatus::ok);
    }
    EXPECT_EQ(k, 56);
    for (; k < 64;) {
        r.end = pose(++k, 0);
        EXPECT_EQ(tp.add_line(r), AddStatus::ok);
    }
    r.end = pose(++k, 0);
    EXPECT_EQ(tp.add_line(r), AddStatus::queue_full);
    EXPECT_EQ(tp.depth(), 64);
}

// M62-M68 outputs: applied when the move they were latched for starts, not before.
struct Write {
    int code;
    int exec;
    int samples;
};
std::vector<Write> digital_writes;
Machine* writing_machine = nullptr;
TEST(TpCore, OutputsApplyWhenTheirMoveStarts) {
    digital_writes.clear();
    Machine m(diamond_settings());
    writing_machine = &m;
    m.tp.set_output_writers({[](int index, char on) {
                                 digital_writes.push_back({index * 10 + on, writing_machine->tp.exec_id(),
                                                           static_cast<int>(writing_machine->samples.size())});
                             },
                             nullptr});
    m.line(pose(10, 0), 100, 1, term_exact);
    m.cycle();  // first move in
    ASSERT_TRUE(m.tp.latch_digital(3, true));  // for the next move
    m.line(pose(10, 10), 100, 2, term_exact);
    ASSERT_TRUE(m.run());
    ASSERT_EQ(digital_writes.size(), 1u);
    EXPECT_EQ(digital_writes[0].code, 31);
    EXPECT_EQ(digital_writes[0].exec, 2);
    // Written in the cycle whose sample is the first one of move 2 off the corner.
    const std::size_t k = static_cast<std::size_t>(digital_writes[0].samples);
    ASSERT_LT(k, m.samples.size());
    EXPECT_EQ(m.samples[k - 1].position, vec(pose(10, 0)));
    EXPECT_GT(m.samples[k].position[1], 0.0);
}

TEST(TpCore, AtSpeedMoveWaitsForTheSpindle) {
    Machine m(diamond_settings());
    m.in.spindle_at_speed = false;
    m.line(pose(10, 0), 100, 1);
    m.program.back().move.atspeed = true;
    for (int k = 0; k < 50; ++k) m.cycle();
    EXPECT_EQ(m.samples.back().position, vec(pose(0, 0)));
    EXPECT_FALSE(m.tp.done());
    m.in.spindle_at_speed = true;
    ASSERT_TRUE(m.run());
    EXPECT_EQ(m.samples.back().position, vec(pose(10, 0)));
}

// The moves before one that waits for the spindle end where the tool rests for it: the planner is
// told so, and the first of them starts at once instead of waiting start_wait (50 ms) for moves
// firtp_tp holds back (pcb2gcode's drill file in LinuxCNC: a 55 ms rest after M3, none in the
// stock planner).
TEST(TpCore, MovesBeforeAnAtSpeedMoveStartAtOnce) {
    TpSettings s = limits_settings();
    Machine m(s, 300.0, 5000.0);
    m.in.spindle_at_speed = false;
    m.line(pose(0, 0, 5), 300, 1, term_parabolic, 0.0, motion_traverse);
    m.line(pose(10, 0, 5), 300, 2, term_parabolic, 0.0, motion_traverse);
    m.line(pose(10, 0, 0), 50, 3);
    m.program.back().move.atspeed = true;
    for (int k = 0; k < 400; ++k) m.cycle();
    const auto moving = [&](std::size_t k) { return m.samples[k].position != m.samples[0].position; };
    std::size_t first = 0;
    while (first < m.samples.size() && !moving(first)) ++first;
    EXPECT_LE(first, 10u);  // 53 periods before: the start waited start_wait
    EXPECT_EQ(m.samples.back().position, vec(pose(10, 0, 5)));  // at rest before the plunge
    m.in.spindle_at_speed = true;
    ASSERT_TRUE(m.run());
    EXPECT_EQ(m.samples.back().position, vec(pose(10, 0, 0)));
}

// A lone move (MDI, or one between two M-codes LinuxCNC waits for motion at) starts once no more
// moves came for three task cycles ([TASK]CYCLE_TIME, 1 ms here: 5 ms with two periods), not after
// the planner's own start_wait of 50 ms (a 53 ms rest before each rapid of a laser program whose
// M3 and M5 enclose every shape). Moves streamed one a period still start as one path.
TEST(TpCore, ALoneMoveStartsAfterThreeTaskCycles) {
    TpSettings s = limits_settings();
    s.task_cycle = 0.001;
    Machine m(s, 300.0, 5000.0);
    m.line(pose(10, 0), 300, 1, term_parabolic, 0.0, motion_traverse);
    for (int k = 0; k < 30; ++k) m.cycle();
    std::size_t first = 0;
    while (first < m.samples.size() && m.samples[first].position == m.samples[0].position) ++first;
    EXPECT_LE(first, 8u);  // 52 with the planner's start_wait
    EXPECT_GE(first, 5u);  // not before the wait
    ASSERT_TRUE(m.run());
    EXPECT_EQ(m.samples.back().position, vec(pose(10, 0)));
}

// Streamed one a period, the chords of a circle (one run of dense blocks, whose start waits for the
// run's end or start_wait) start as they did without the task cycle: moves keep coming.
TEST(TpCore, AStreamedDenseRunStartsAsWithoutTheTaskCycle) {
    auto samples = [](double task_cycle) {
        TpSettings s = limits_settings();
        s.task_cycle = task_cycle;
        Machine m(s, 300.0, 5000.0);
        for (int k = 1; k <= 180; ++k) {
            const double a = 2.0 * std::numbers::pi * k / 360.0;
            m.line(pose(20.0 * std::sin(a), 20.0 - 20.0 * std::cos(a)), 250, k, term_parabolic, 0.5);
        }
        EXPECT_TRUE(m.run());
        return m.samples;
    };
    const std::vector<AxisState> without = samples(0.0), with = samples(0.001);
    ASSERT_EQ(with.size(), without.size());
    for (std::size_t k = 0; k < with.size(); ++k) ASSERT_EQ(with[k].position, without[k].position) << "period " << k;
}

// The servo-thread calls allocate nothing once the planner is built.
TEST(TpCore, AddsAndCyclesDoNotAllocate) {
    TpSettings s = diamond_settings();
    s.filter_times = {0.06, 0.05, 0.0, 0.0};
    TpCore tp(s);
    tp.set_axis_limits(limits(300), limits(5000));
    CycleInputs in;
    MoveRequest r;
    r.vel = 200;
    r.end = pose(1, 1);
    tp.add_line(r);
    tp.run_cycle(in);  // builds the planner with the limits
    const long before = firtp::test::allocation_count();
    for (int k = 2; k < 400; ++k) {
        tp.set_id(k);
        tp.set_term_cond(term_parabolic, 0.05);
        r.end = pose(k, (k % 2) * 1.0);
        if (!tp.full()) tp.add_line(r);
        if (k == 100) tp.add_arc(r, {{static_cast<double>(k - 1), 5, 0}, {0, 0, 1}, 0});
        tp.latch_digital(1, k % 2 == 0);
        tp.run_cycle(in);
        (void)tp.exec_tag();
    }
    tp.pause();
    for (int k = 0; k < 300; ++k) tp.run_cycle(in);
    tp.resume();
    tp.abort();
    for (int k = 0; k < 1000 && !tp.done(); ++k) tp.run_cycle(in);
    tp.clear();
    tp.set_position(pose(3, 3));
    EXPECT_EQ(firtp::test::allocation_count() - before, 0);
}

}  // namespace
