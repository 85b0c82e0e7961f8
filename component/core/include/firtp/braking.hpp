// A stop from a velocity the machine already has, found at a start (the component restarted, or
// its enable rose, while the axes moved). The stop is the chain's response to a velocity pulse's
// falling edge: v (1 - Sigma(t)) over [0, Td] (Eq. 6), so it keeps the motion's smoothness and
// its peak acceleration and jerk are |v| max Sigma' and |v| max |Sigma''|.
#pragma once

#include <firtp/fir_chain.hpp>
#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

namespace firtp {

// Peaks of the chain's response per unit of velocity stopped.
struct BrakingPeaks {
    double acceleration = 0.0;  // max Sigma'(t), 1/s
    double jerk = 0.0;          // max |Sigma''(t)|, 1/s^2
};

// Init only: samples the chain's step response densely (and at its knots).
BrakingPeaks braking_peaks(const FirChain& chain);

// The share s in (0, 1] of `velocity` that the chain can stop within the axis limits: s v is
// within every max_velocity and stopping it stays within max_acceleration and max_jerk (limits of
// 0 are not checked). Real-time: O(axes).
double braking_share(const BrakingPeaks& peaks, const MachineLimits& limits, const AxisVector& velocity);

// Where a stop from `velocity` at `position` comes to rest: position + velocity * Td / 2.
inline AxisVector braking_rest(const FirChain& chain, const AxisVector& position, const AxisVector& velocity) {
    return position + velocity * (0.5 * chain.delay());
}

}  // namespace firtp
