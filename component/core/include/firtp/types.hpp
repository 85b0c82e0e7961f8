// Plain data that flows through the planner: blocks in, axis states out.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>

namespace firtp {

// X Y Z A B C U V W, in this order everywhere (LinuxCNC's EmcPose order).
constexpr int max_axes = 9;
constexpr std::array<char, max_axes> axis_letters{'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'};
using AxisVector = Eigen::Matrix<double, max_axes, 1>;

// Blocks shorter than this (units) are skipped: they have no direction to plan with.
constexpr double min_block_length = 1e-9;

// Longest dwell a block may ask for, s (a day): the servo clock counts it in whole periods.
constexpr double max_dwell = 86400.0;

// Values match LinuxCNC's EMC_MOTION_TYPE_* so they pass through unchanged.
enum class MotionType : std::uint8_t { traverse = 1, feed = 2 };

// How the block ends: G61/G61.1 stop exactly, G64 blends within the block's tolerance.
enum class Termination : std::uint8_t { exact_stop, blend };

// One commanded straight move, in machine units (mm, degrees) and seconds.
struct Block {
    AxisVector target = AxisVector::Zero();  // absolute end point
    double feed = 0.0;                       // path speed F, units/s (> 0)
    Termination termination = Termination::blend;
    double tolerance = 0.0;                  // epsilon at the corner that ends this block, units (> 0 when blending)
    MotionType type = MotionType::feed;
    std::int64_t line = 0;                   // source line, reported back while the block executes
    // G4: the tool rests at least this long (s) where the previous block stopped before this block
    // starts (a dwell forces that stop). Last, so that brace lists of the fields above still fit.
    double dwell = 0.0;
};

// Commanded state of every axis at one servo tick.
struct AxisState {
    double time = 0.0;  // seconds since the planner started
    AxisVector position = AxisVector::Zero();
    AxisVector velocity = AxisVector::Zero();
    AxisVector acceleration = AxisVector::Zero();
    AxisVector jerk = AxisVector::Zero();
    std::int64_t line = 0;  // line of the newest block that has started moving (0 when idle)
};

// When Planner::add plans the block: now (each add pays its own planning: what a servo period's
// budget measures), or at the next update, once for every block added since (a caller that adds
// many blocks at once, as firtp plan refilling its window: the path's end, re-planned and checked
// at every add, is then planned once).
enum class Planning : int { now, at_update };

// What Planner::add and Planner::update return. Negative: the block is refused and nothing changed;
// why, in words, is Planner::refusal().
enum class Result : int {
    ok = 0,              // add: queued
    queue_full = 1,      // add: nothing changed; try again after some periods
    skipped = 2,         // add: shorter than min_block_length, nothing to plan (the goal stays)
    working = 3,         // update: moving, or blocks wait
    finished = 4,        // update: at rest and nothing waits
    invalid_block = -1,  // a value that cannot work: NaN, infinite or non-positive feed, bad
                         // tolerance, a pulse L / F longer than the servo clock counts
    absent_axis = -2,    // moves an axis the machine does not have (no acceleration limit)
    infeasible = -3,     // the paper's chain: no feed, down to a stop, keeps the block within its
                         // tolerance and the axis limits
};

// The block was refused (add): it must not run.
constexpr bool refused(Result r) { return static_cast<int>(r) < 0; }

}  // namespace firtp
