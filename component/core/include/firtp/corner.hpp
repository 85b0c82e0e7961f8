// One corner: the incoming pulse (ending at t = 0) and the outgoing pulse (starting at Td - Tk),
// with the tool position measured from the programmed corner point. Exact as long as no third
// block moves inside the overlap, which the planner's clamp guarantees.
#pragma once

#include <firtp/fir_chain.hpp>
#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

namespace firtp {

struct CornerModel {
    const FirChain* chain = nullptr;
    AxisVector in_delta = AxisVector::Zero();   // displacement of the incoming pulse
    double in_tv = 0.0;                         // its width (Eq. 5)
    AxisVector out_delta = AxisVector::Zero();
    double out_tv = 0.0;

    // Tool position relative to the corner point at time t after the incoming pulse ended.
    AxisVector offset(double t, double Tk) const;
    // Closest approach to the corner point over the overlap (continuous time).
    double corner_error(double Tk) const;
    // The same for the path through servo samples (straight between samples, as the drives follow
    // it), at the worst phase of the sampling grid: the chord that spans the closest approach.
    double sampled_corner_error(double Tk, double period) const;
    // Largest distance from the two programmed segments over the overlap.
    double contour_error(double Tk) const;
};

// Largest Tk in [0, Tk_max] whose error (per `meaning`, sampled at `period`) is <= epsilon, or 0
// (a stop, which the planner puts on a servo sample so the tool rests on the corner).
// Equal feeds with both pulses at least Tk_max long use the closed form; anything else is solved
// on the model. The returned Tk always satisfies the bound; epsilon = +inf gives Tk_max.
double solve_overlap(const CornerModel& corner, double epsilon, ToleranceMeaning meaning,
                     double period, double Tk_max);

// Change of direction between two displacements, radians in [0, pi].
double turn_angle(const AxisVector& in_delta, const AxisVector& out_delta);

}  // namespace firtp
