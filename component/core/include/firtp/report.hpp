// What the planner tells about its decisions: per corner, and counts.
#pragma once

#include <firtp/types.hpp>

#include <cstdint>

namespace firtp {

// What limited the speed at a junction (for the report).
enum class CornerBound : std::uint8_t {
    feed,         // the programmed feed (or an axis velocity limit) on one side
    tolerance,    // the corner's tolerance with its most loaded axis at the acceleration limit
    room,         // the block before or after is too short to change speed in (dense paths)
    lookahead,    // a later corner or the stop at the end of the known path
    checked,      // the closed-form estimate was lowered after the exact check
    stop,         // an exact stop: asked for, a reversal, or the end of the program
    stop_pays,    // a stop where blending would take longer (a slow turn between long blocks)
};
const char* describe(CornerBound bound);

// What the planner decided at the junction between two blocks.
struct CornerReport {
    std::int64_t line = 0;                  // line of the block that ends at the corner
    AxisVector point = AxisVector::Zero();  // programmed corner point
    double beta = 0.0;                      // change of direction, rad
    double speed_in = 0.0;                  // command speed before and after the corner, units/s
    double speed_out = 0.0;
    double epsilon = 0.0;                   // tolerance asked for (+inf: none)
    double predicted_error = 0.0;           // closest approach found by the check (with the chord margin)
    bool exact_stop = false;
    CornerBound bound = CornerBound::feed;
    int axis = -1;                          // the most loaded axis of the corner step (tolerance, room)
    double Tk = 0.0;            // overlap used (limit-driven: turns of 120 degrees and more, else 0)
    double Tk_tolerance = 0.0;  // the paper's mode only: what the tolerance alone allows
};

// Counts since construction.
struct PlannerStats {
    std::uint64_t slowed = 0;    // blocks planned below their feed
    std::uint64_t crawling = 0;  // ... below 0.1 % of it
    std::uint64_t refused = 0;   // blocks no speed could plan (paper mode: no feed passed the check)
    std::uint64_t checks_failed = 0;  // plans the exact check turned back (corner speed lowered)
    std::uint64_t checks = 0;         // plans the exact check measured
    std::uint64_t legs_checked = 0;   // the legs those checks summed: their context and the changed tail
    std::uint64_t unfit = 0;          // segment plans whose legs did not cover the block (a defect)
    std::uint64_t batches_undone = 0; // batches (added at_update, or waiting blocks joining) whose plan failed: one by one
    std::uint64_t segments_planned = 0;  // forward plans of a segment (the passes' work)
    std::uint64_t rejoined = 0;       // blocks that waited beyond the window's reach and joined it
    std::uint64_t gathered = 0;       // ... of them, joining a window still filling under way (fills_under_way)
    std::uint64_t join_steps = 0;     // steps of such joins taken in a later period than the join's first
    std::uint64_t joins_hurried = 0;  // ... joins finished at once: a freeze or a start came near what they change
    std::uint64_t overlapped = 0;     // corners passed with the blocks' pulses overlapping (Tk > 0, two steps)
};

}  // namespace firtp
