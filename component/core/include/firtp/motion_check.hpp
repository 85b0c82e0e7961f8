// Checks of planned motion in closed form, on the piecewise polynomials themselves (no sampling).
//
// Limits: every edge of every leg is a velocity step smoothed by its kernel. For two moving
// averages the acceleration of a step is a trapezoid and its jerk piecewise constant, so the sum
// over all steps is piecewise linear (acceleration) and piecewise constant (jerk) between the
// kernels' knots: sweeping the knots in time order finds the largest acceleration and jerk
// exactly, and the largest velocity at a knot or where an acceleration crosses zero. A chain of
// more stages is bounded by its first two (the others are moving averages, which do not raise a
// peak). Where one leg falls and the next rises on the same step (a junction: the same kernel at
// the same time), the two edges are one, of the velocities' difference: half the knots, and no
// cancelling of two large jumps in the sums.
//
// Corners: the tool's position near a corner point P is a sum over the legs in motion; its
// closest approach is at most the distance at any time, found here by Newton's method on the
// distance from the time the command passes P. The drives go straight from servo sample to servo
// sample (at t = k period on the common clock), so the chords between the samples around that
// time are measured too: the error is the larger of the two.
#pragma once

#include <firtp/kernel.hpp>
#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <span>

namespace firtp {

// A leg with its rising kernel starting at `rise` seconds on a common clock.
struct TimedLeg {
    AxisVector delta = AxisVector::Zero();
    double tv = 0.0;
    double rise = 0.0;
    double fall = 0.0;  // the falling kernel starts at rise + fall
    Kernel rising;
    Kernel falling;

    double start() const { return rise + std::min(0.0, fall); }
    double finish() const { return rise + std::max(fall + falling.width(), rising.width()); }

    // Set by index_legs(): where the leg starts along the legs' path (from the first leg's start),
    // its two steps' centres and half the widest kernel of the set (0: not indexed).
    AxisVector before = AxisVector::Zero();
    double rise_centre = 0.0;
    double fall_centre = 0.0;
    double reach = 0.0;
    int axes = max_axes;  // the axes any leg of the set moves: 1 + the last with a non-zero delta
};

// Indexes legs in path order (their steps' centres do not decrease) so that relative_state()
// visits only the legs in motion at a time: a leg whose falling centre is more than `reach`
// before t has ended, one whose rising centre is more than `reach` after t has not begun. O(n).
void index_legs(std::span<TimedLeg> legs);

struct LimitCheck {
    bool ok = true;
    double time = 0.0;  // where the first excess was found
    int axis = 0;
    int derivative = 0;  // 1 velocity, 2 acceleration, 3 jerk
    double value = 0.0;
};

// The largest |velocity|, |acceleration| and |jerk| of the legs' sum on [from, to] against
// `limits` (relative slack 1e-8; limits of 0 are not checked). A one-stage kernel's jump in
// acceleration counts as jump / period of jerk, as a drive differentiating the samples sees it.
// Allocation-free after construction: sized for `max_legs` legs.
class LimitSweep {
public:
    explicit LimitSweep(std::size_t max_legs);
    LimitCheck check(std::span<const TimedLeg> legs, double from, double to, const MachineLimits& limits,
                     double period);

    // A step's jumps: jump (the first limits.axes entries) in the derivative of order `order`
    // (1 velocity, 2 acceleration, 3 jerk) at some of its knots, -jump at the others.
    struct Edge {
        AxisVector jump;
        AxisVector step;  // the velocity it changes by in all
        int order;
    };
    struct Knot {
        double t;
        std::uint32_t edge;
        std::uint32_t flags;  // flip: -jump; first, last: the step's first and last knot
        static constexpr std::uint32_t flip = 1, first = 2, last = 4;
    };

private:
    template <int Axes>
    LimitCheck sweep(std::span<const TimedLeg> legs, double from, double to, const MachineLimits& limits, double period);
    std::vector<Edge> edges_;
    std::vector<Knot> knots_;
};

// Position relative to the end of legs[corner] (the corner point) at time t, with velocity,
// acceleration and jerk: legs up to `corner` count S - 1, later ones S. O(legs in motion at t)
// when indexed (index_legs), else O(legs).
AxisState relative_state(std::span<const TimedLeg> legs, std::size_t corner, double t);
// Its position alone, bit for bit the same (the closest approach's chords need no derivatives).
AxisVector relative_position(std::span<const TimedLeg> legs, std::size_t corner, double t);

struct Approach {
    double distance = 0.0;  // the larger of smooth and sampled
    double time = 0.0;      // of the smooth path's approach
    double smooth = 0.0;    // of the smooth path from the corner point, at `time`
    double sampled = 0.0;   // of the chords between the samples within sampled_chords periods of it
    double latest = 0.0;    // the latest time the search looked at the path
};

constexpr int sampled_chords = 3;
// closest_approach's Newton search: at most this many steps from the guess, each at most this many
// periods (it evaluates the path at no more than approach_steps - 1 of them).
constexpr int approach_steps = 6;
constexpr double approach_step_periods = 4.0;
// How far before its guess closest_approach may look at the path (the search, then the chords).
constexpr double approach_reach(double period) {
    return ((approach_steps - 1) * approach_step_periods + sampled_chords + 1) * period;
}
constexpr int max_phases = 16;  // sample grids closest_approach takes (more are taken as 16)

// What closest_approach may lean on to spare sampling the chords between the samples. A chord
// strays from the path it spans by at most period^2 / 8 |a|max over its period.
struct ApproachBounds {
    double acceleration = HUGE_VAL;  // |a| near the approach, e.g. the limits the sweep held
    double jerk = HUGE_VAL;          // |j| near it: |a| within a period of the approach from the one there
    double enough = 0.0;             // an answer at most this passes: where the bound does, it is the answer
    double too_far = HUGE_VAL;       // a smooth approach beyond this fails whatever the chords (returned as it is)
};

// An upper bound of the closest approach of the path to the corner point at the end of
// legs[corner], searched from time `guess`; samples at t = k period, or with `phases` > 1 the worst
// of the sample grids shifted by 1 / phases of a period (a scaled clock samples off the grid).
// With `bounds`: where the guess's own distance, or the smooth approach's, plus the chords' sag is
// `enough`, that is the answer (every point of the path is at least as far as the closest, and the
// chord across any time is within the sag of the path there); nothing is sampled then.
// `offset`: the corner point lies that far past the end of legs[corner] (a corner the legs
// overlap: the leg across it ends past the corner, lookahead.hpp).
Approach closest_approach(std::span<const TimedLeg> legs, std::size_t corner, double guess, double period,
                          int phases = 1, const ApproachBounds& bounds = {},
                          const AxisVector& offset = AxisVector::Zero());

// |acceleration| and |jerk| of legs whose steps are all smoothed by `chain` (the paper's mode),
// bounded within [from, to]: a step acts for Td from its kernel's start; the chain's density is at
// most 1 / T1 (a moving average of anything is) and its slope at most 1 / (T1 T2) (jerk: none with
// one stage), T1 >= T2 its longest filters. So |a| <= sum |v| / T1 over the steps that start
// within [from - Td, to], and |j| <= that sum / (T1 T2).
ApproachBounds chain_bounds(std::span<const TimedLeg> legs, const FirChain& chain, double from, double to);

// The largest distance from the programmed path (the legs commanded nearby, as straight
// segments) of the samples (t = k period) within `width` / 2 of time `at`, the corner at the end
// of legs[corner] (contour tolerance; `width`: the widest kernel). `latest`, when given: the latest
// time it looked at the path (as Approach::latest).
double contour_error(std::span<const TimedLeg> legs, std::size_t corner, double at, double width, double period,
                     double* latest = nullptr);
// How far before `at` contour_error looks at the samples.
constexpr double contour_reach(double width, double period) { return 0.5 * width + period; }

}  // namespace firtp
