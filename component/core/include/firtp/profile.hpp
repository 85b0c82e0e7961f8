// The speed profile of one block: up to three legs at constant command speed (entry a, cruise p,
// exit b) joined by speed steps along the block, between the steps at its two ends.
//
// Principle: every step k has a kernel two_stage(T1_k, T2) (kernel.hpp), T2 the jerk time of its
// regime (the axes moving in it: lookahead.hpp, Regime). Steps of one T2 are a moving average of
// length T2 of a piecewise linear velocity W whose ramps are boxes of acceleration dV_k / T1_k,
// centred on the steps. The limits hold when
//   - each box is within the acceleration limits (T1_k = max_a |dV_a| / A_a),
//   - boxes do not overlap: consecutive steps are at least (T1_k + T1_k+1) / 2 apart, and
//   - boxes whose accelerations have opposite signs on an axis (and together exceed J_a T2) are
//     at least T2 apart, so the moving average never sees the acceleration swing by more than
//     J_a T2 within its window: the jerk is at most J_a.
// Velocity stays between the legs' velocities. These are the spacing rules (spacing()); the
// planner keeps them at every step, so the limits need no search. Steps of different jerk stages,
// and steps whose kernels are sized to themselves (starts and stops: sized_kernel), do not share
// a moving average: their kernels stay apart. A ramp that shares a corner's jerk stage in a dense
// run's regime ends its kernel by the corner's middle, so that its own lead does not add to the
// corner's error there (the corner's speed is found for the corner's step alone, junction.hpp).
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <array>
#include <cstdint>

namespace firtp {

// One end of a step as the spacing rules see it: the box width T1, the direction of dV and the
// step's jerk stage T2 (dense runs use their own, see lookahead.hpp).
struct StepShape {
    double box = 0.0;                       // T1, s (0: no step)
    AxisVector direction = AxisVector::Zero();  // of dV (unit or zero)
    double t2 = 0.0;
    double unit_box = -1.0;  // SpacingRules::unit_box(direction), where the caller knows it (< 0: not)
    bool own = false;        // its kernel is sized to it alone (sized_kernel): it shares no moving average
    // Its boxes may reach the acceleration limits (a sparse regime's step): boxes of opposite sign
    // on an axis within its T2 may need a jerk gap (needs_gap at that T2).
    bool gapped = false;
};

// The shared constants of the spacing rules.
struct SpacingRules {
    MachineLimits limits;
    double t2 = 0.0;  // the machine's jerk time: the widest sparse one, every axis' max A / J

    // Least distance in command time between the centres of consecutive steps x then y. Steps
    // with different jerk stages do not share the moving average: their kernels stay apart. Always
    // at least half the difference of their widths: kernels start in the steps' order.
    double spacing(const StepShape& x, const StepShape& y) const;
    // True when boxes in directions x and y, steps of jerk stage `stage`, need a jerk gap of that
    // stage between them (opposite signs on an axis whose accelerations at the limit would swing
    // by more than J times it), as spacing() finds it.
    bool needs_gap(const AxisVector& x, const AxisVector& y, double stage) const;
    // T1 per unit of a step in direction d, max_a |d_a| / A_a (the same for -d): the box heights
    // the jerk gaps compare are |d_a| / that.
    double unit_box(const AxisVector& d) const;
};

// Whether the steps of one block's profile need jerk gaps, kept across the calls of a search whose
// step directions do not change (the entry's, +-u, the exit's): 0 not known yet, 1 no, 2 yes.
struct GapMemo {
    std::array<std::uint8_t, 8> pair{};
};

// A long block between its end steps, at given entry, cruise and exit speeds.
struct ProfileInput {
    double length = 0.0;
    double alpha = 0.0;          // T1 per unit of speed change along the block: max_a |u_a| / A_a
    // A ramp next to a corner smoothed in a dense run's regime shares that regime's jerk stage
    // (lookahead.hpp, Segment::in_ramp): the ramp a -> p takes the entry's (in_t2, in_alpha), the
    // ramp p -> b the exit's. in_t2 / out_t2 < 0: alpha and the block's own jerk stage (t2).
    double in_alpha = 0.0, in_t2 = -1.0;
    double out_alpha = 0.0, out_t2 = -1.0;
    // A ramp in a sparse corner's longer stage, with the block's own boxes (their jerk only
    // falls): it shares the corner's moving average and keeps its jerk gaps (StepShape::gapped).
    bool in_gapped = false, out_gapped = false;
    double t2 = -1.0;  // the block's own jerk stage (its sparse regime's; < 0: the machine's)
    AxisVector u = AxisVector::Zero();
    double u_unit_box = -1.0;    // SpacingRules::unit_box(u), where the caller knows it (< 0: not)
    StepShape in;                // the step at the start (before the entry leg)
    StepShape out;               // the step at the end (after the exit leg)
    // Extra time on the entry and exit legs: across a junction, this block's ramps and the
    // neighbour's may have opposite signs, and the junction step alone may not keep them T2 apart.
    double in_reserve = 0.0;
    double out_reserve = 0.0;
    // The entry step is already under way: its centre was this long ago (command time), and the
    // next step's kernel must not start before now. -inf: no such constraint.
    double entry_elapsed = -1e300;
    // Where a search keeps the jerk gaps of these directions (nullptr: found at each call).
    GapMemo* gaps = nullptr;
};

struct ProfileLegs {
    double a = 0.0, p = 0.0, b = 0.0;     // speeds of the entry, cruise and exit legs
    double x0 = 0.0, xp = 0.0, x1 = 0.0;  // their durations (command time); 0 where a leg is merged
    bool fits = false;
    double margin = 0.0;  // length left over (+ the rounding allowance): >= 0 about where it fits
    double duration() const { return x0 + xp + x1; }
};

// The shortest legs for speeds a -> p -> b (a ramp step a -> p and p -> b where they differ), and
// whether they fit in the block's length. The remaining length goes to the fastest leg.
ProfileLegs profile_legs(const SpacingRules& rules, const ProfileInput& in, double a, double p, double b);

}  // namespace firtp
