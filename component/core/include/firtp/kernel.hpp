// The smoothing of one velocity step: a chain of moving averages (Eq. 1-2), in closed form.
//
// Principle: every velocity change of the command (a block starting, stopping, turning a corner,
// changing speed) is a step dV at a time tau. A kernel h of width Td, symmetric about its middle,
// turns it into smooth motion that starts Td/2 before tau and ends Td/2 after it; the position far
// from tau is exactly the command's. A step's kernel is chosen for that step alone, so each move
// uses the machine's limits (Sencer et al. 2015 use one chain for every block; Tajima and Sencer,
// IJMTM 2016, choose the smoothing per corner).
//
// In the limit-driven mode a kernel is two moving averages: T1 = max over the axes of
// |dV_a| / A_a, so the step's acceleration reaches the limit on its most loaded axis (Eq. 4:
// a = dV / T1), and T2, the machine's jerk time max A_a / J_a, shared by every step. A shared T2
// makes the whole motion one moving average of a piecewise linear velocity (see planner.hpp),
// which is what bounds the jerk. In the paper's mode every step uses the fixed chain (FirChain).
#pragma once

#include <firtp/fir_chain.hpp>
#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

namespace firtp {

struct Kernel {
    double a = 0.0;  // the longer stage, s (0 with b = 0: a sharp step, no smoothing)
    double b = 0.0;  // the shorter stage, s (0: one stage)
    const FirChain* chain = nullptr;  // the paper's fixed chain instead of a and b

    double width() const { return chain != nullptr ? chain->delay() : a + b; }  // Td (Eq. 6)
    // Response to a unit velocity step whose smoothing starts at t = 0 (position, velocity 0 -> 1,
    // acceleration, jerk).
    StepSample step(double t) const;
    double step_position(double t) const;  // step(t).position, bit for bit, without the derivatives
    double position(double t) const;
    // How far the smoothed motion leads the command at the step's middle, per unit of dV: R(Td/2).
    // For two stages (3 a^2 + b^2) / (24 a); the corner error of a turn at speed V is 2 V s lead()
    // (Eq. 13/14 at full overlap, s = sin(beta / 2)).
    double lead() const;
    // The same at `offset` seconds from the middle: R(Td/2 + |offset|) - |offset|, 0 beyond Td/2.
    double lead_at(double offset) const;
    // Largest acceleration and jerk per unit of dV (the first two stages; more only lower them).
    double peak_acceleration() const;
    double peak_jerk() const;  // +inf for one stage
};

// Two moving averages of lengths t1 and t2 (any order, >= 0).
Kernel two_stage(double t1, double t2);

// T1 of a step dV: max over the axes of |dV_a| / A_a (0 for axes without an acceleration limit).
double acceleration_time(const MachineLimits& limits, const AxisVector& dv);

// The kernel of a step dV at `limits` (smoothing_limits: parameters.hpp): two_stage(acceleration_time, jerk_time).
Kernel step_kernel(const MachineLimits& limits, const AxisVector& dv);

}  // namespace firtp
