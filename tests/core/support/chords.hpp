// A dense path with thousands of blocks waiting, measured whole: examples/polygon360.ngc's chords
// on firtp_tp's window.
#pragma once

#include "limits.hpp"
#include "rate_run.hpp"
#include "within.hpp"

#include <firtp/measure.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace firtp::test {

// A run that has not ended after 400 s of motion fails (without a defect these end far sooner).
inline std::int64_t run_ticks(const PlannerParameters& p) { return static_cast<std::int64_t>(400.0 / p.period); }

// examples/polygon360.ngc's circle of R20 in 0.35 mm chords, F 300 mm/s, G64 P0.5, rising 0.05
// mm a turn so the measurement never meets the path again: a dense path, whose stop spans the most
// blocks.
inline std::vector<Block> helix_chords(int blocks) {
    std::vector<Block> program;
    for (int i = 1; i <= blocks; ++i) {
        const double angle = 2.0 * M_PI * i / 360.0;
        Block b;
        b.target = AxisVector::Zero();
        b.target[0] = 20.0 * std::cos(angle) - 20.0;
        b.target[1] = 20.0 * std::sin(angle);
        b.target[2] = 0.05 * i / 360.0;
        b.feed = 300.0;
        b.tolerance = 0.5;
        b.line = i;
        program.push_back(b);
    }
    return program;
}

// The built-in machine with firtp_tp's window (4096 blocks) and overrides up to 150 %.
inline PlannerParameters deep_queue_machine() {
    PlannerParameters machine = builtin_machine();
    machine.queue_capacity = 4096;
    machine.max_rate = 1.5;
    return machine;
}

}  // namespace firtp::test
