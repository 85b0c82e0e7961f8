// A step's jerk stage comes from the axes that move in it (lookahead.hpp, dense_regime and
// sparse_regime): a machine's slow-jerk axis (a rotary axis, a heavy Z) no longer widens the stage
// of dense runs, ramps and corners it takes no part in. Measured on the samples: the limits (also
// in 1 ms differences), the corners, the end.
#include "support/chords.hpp"
#include "support/random_machine.hpp"

#include <firtp/planner.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace firtp {
namespace {

// X, Y, Z at 300 mm/s, 5000 mm/s^2, 1e6 mm/s^3, and a fourth axis with a 100 ms jerk stage
// (500 / 5e3) whose jerk is `fourth_jerk`.
PlannerParameters machine_with_fourth_axis(double fourth_jerk) {
    PlannerParameters p = test::deep_queue_machine();
    p.max_rate = 1.0;
    p.limits = test::uniform_limits(300.0, 5000.0, 1e6);
    p.limits.axes = 4;
    p.limits.axis[3] = {100.0, 500.0, fourth_jerk};
    return p;
}

// 0.1 mm chords of an XY circle at 200 mm/s, G64 P0.01: one dense run.
std::vector<Block> xy_chords() {
    std::vector<Block> program;
    const double radius = 0.1 * 360.0 / (2.0 * M_PI);
    for (int i = 1; i <= 720; ++i) {
        const double angle = 2.0 * M_PI * i / 360.0;
        Block b;
        b.target = AxisVector::Zero();
        b.target[0] = radius * std::cos(angle) - radius;
        b.target[1] = radius * std::sin(angle);
        b.feed = 200.0;
        b.tolerance = 0.01;
        b.line = i;
        program.push_back(b);
    }
    return program;
}

// `program` on X and Y takes about as long with the fourth axis' jerk at 5e3 (a 100 ms stage) as at
// 1e6, and keeps every limit, tolerance and its end there.
void expect_fourth_axis_left_alone(const std::vector<Block>& program, const char* what) {
    const PlannerParameters slow = machine_with_fourth_axis(5e3), fast = machine_with_fourth_axis(1e6);
    const test::RateRun with_slow = test::run_with_rates(slow, program, {}, test::run_ticks(slow));
    const test::RateRun with_fast = test::run_with_rates(fast, program, {}, test::run_ticks(fast));
    std::printf("%s: %zu periods with a slow fourth axis, %zu with a fast one\n", what, with_slow.samples.size(),
                with_fast.samples.size());
    EXPECT_LE(with_slow.samples.size(), with_fast.samples.size() + with_fast.samples.size() / 100);
    test::expect_within(with_slow, program, slow);
}

// (Judged by every axis, the run's stage was the fourth axis' 100 ms: 2,584 periods against 581.)
TEST(AxisStages, AnAxisThatDoesNotMoveLeavesTheRunsJerkStageAlone) { expect_fourth_axis_left_alone(xy_chords(), "XY chords"); }

// A square spiral of 40 blocks from 2 mm, each turning 90 degrees, on X and Y at 200 mm/s, G64
// P0.05: sparse blocks, their ramps and corners.
std::vector<Block> xy_square_turns() {
    std::vector<Block> program;
    AxisVector at = AxisVector::Zero();
    for (int i = 0; i < 40; ++i) {
        const double side = 2.0 + 0.25 * i;
        at[0] += side * std::cos(0.5 * M_PI * i);
        at[1] += side * std::sin(0.5 * M_PI * i);
        Block b;
        b.target = at;
        b.feed = 200.0;
        b.tolerance = 0.05;
        b.line = i + 1;
        program.push_back(b);
    }
    return program;
}

// (With every axis' T2, 100 ms, on every ramp and corner: 5,213 periods against 2,648.)
TEST(AxisStages, AnAxisThatDoesNotMoveLeavesRampsAndCornersAlone) { expect_fourth_axis_left_alone(xy_square_turns(), "XY turns"); }

// firtp_cliffs seed 2 program 293: 17 blocks of 0.56 mm on X and Y, three of them G61, on a machine
// whose axis 3 (not moving) has a jerk stage of 28 ms at the program's tolerance. With every
// tolerance a quarter larger, its G61 blocks joined the dense runs, whose stage was axis 3's, and
// the program took 902 periods instead of 485 (now 362 both).
TEST(AxisStages, ARaisedToleranceDoesNotSlowARunOfAxesThatDoNotSetItsStage) {
    std::mt19937_64 rng(2);
    for (int k = 0; k < 293; ++k) test::cliffs_program(rng);
    const test::RandomCase c = test::cliffs_program(rng).c;
    std::vector<Block> looser = c.blocks;
    for (Block& b : looser) b.tolerance *= 1.25;
    const test::RateRun base = test::run_with_rates(c.parameters, c.blocks, {}, test::run_ticks(c.parameters));
    const test::RateRun raised = test::run_with_rates(c.parameters, looser, {}, test::run_ticks(c.parameters));
    std::printf("seed 2 program 293: %zu periods, %zu with the tolerance raised\n", base.samples.size(), raised.samples.size());
    EXPECT_LE(raised.samples.size(), base.samples.size());
    test::expect_within_random(base, c.blocks, c.parameters);
    test::expect_within_random(raised, looser, c.parameters);
}

}  // namespace
}  // namespace firtp
