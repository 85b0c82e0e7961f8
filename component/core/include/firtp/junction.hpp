// Where two blocks meet: the turn, and the highest speed at which the tool may pass it.
//
// Kinematic corner smoothing (Tajima and Sencer, "Kinematic corner smoothing for high speed
// machine tools", IJMTM 108, 2016): the command passes the corner at speed V; its velocity steps
// from V u_in to V u_out, and the step's kernel (kernel.hpp) smooths the turn. The kernel's first
// stage T1 = V alpha (alpha = max_a |du_a| / A_a) makes the most loaded axis reach its
// acceleration limit; the corner error is then
//     err(V) = |V du| lead(T1, T2) = 2 s V (3 T1^2 + T2^2) / (24 T1)        (T1 >= T2)
// (Eq. 13/14 at full overlap), which grows with V, so the highest corner speed the tolerance
// allows has a closed form (corner_speed). Speed changes before and after the corner are steps of
// their own, planned by the look-ahead (lookahead.hpp).
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

namespace firtp {

struct Turn {
    AxisVector du = AxisVector::Zero();  // u_out - u_in
    AxisVector direction = AxisVector::Zero();  // du / |du| (zero when straight on)
    double s = 0.0;                      // |du| / 2 = sin(beta / 2)
    double beta = 0.0;                   // change of direction, rad
    double alpha = 0.0;                  // T1 per unit of corner speed: max_a |du_a| / A_a, s/(unit/s)
    bool reversal = false;               // the path goes back on itself: the tool stops there
};

// u_in, u_out: unit directions (over all nine axes) of the blocks meeting at the corner.
Turn make_turn(const AxisVector& u_in, const AxisVector& u_out, const MachineLimits& limits);

// Turns smaller than this (rad) are straight on: no corner, nothing to bound.
constexpr double straight_angle = 1e-9;

// The highest V with 2 s V lead(two_stage(V alpha, t2)) <= epsilon; +inf when the turn is
// straight or nothing limits it.
double corner_speed(double alpha, double t2, double s, double epsilon);

// How far the path through the servo samples (straight between samples) can lie from the smooth
// path, for an acceleration of at most `acceleration` changing by at most `jerk` per second:
// (a + j T) T^2 / 8, the change within a period at most 2 a (a step of a jerk-free axis). For the
// closed-form caps; the exact check measures the chords themselves.
double chord_margin(double acceleration, double jerk, double period);

// corner_speed() with the chord margin of the corner step's own peak acceleration,
// V |du| / max(V alpha, t2), added to the error (|du| = `du`, |jerk| at most `jerk`).
double sampled_corner_speed(double alpha, double t2, double s, double du, double jerk, double period, double epsilon);

}  // namespace firtp
