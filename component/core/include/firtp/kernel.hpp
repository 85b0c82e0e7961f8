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
// which is what bounds the jerk. A start from rest and a stop to rest share no moving average
// with anything: each gets the narrowest kernel its own step allows (sized_kernel), the
// jerk-limited S-curve of that step. In the paper's mode every step uses the fixed chain (FirChain).
#pragma once

#include <firtp/fir_chain.hpp>
#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <algorithm>

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

// Inline: the checks evaluate steps tens of millions of times a program.
namespace kernel_detail {

// A kernel starting within this of the sample has not started: where one step ends a leg and starts
// the next, the two legs' clocks may round to either side of it, and a sample would see half the
// step's jerk (its motion so far, ~J t^3 / 6, is nothing).
constexpr double started_after = 1e-9;  // s

// R(t) of two moving averages a >= b > 0 (the integral of the step response): a cubic ramp-in,
// a parabola, a cubic ramp-out; R(t) = t - (a + b) / 2 beyond.
inline StepSample two_stage_step(double a, double b, double t) {
    const double td = a + b;
    if (t >= td) return {t - 0.5 * td, 1.0, 0.0, 0.0};
    if (b <= 0.0) {  // one stage: a parabola, the acceleration a box (its jerk a pair of impulses)
        return {t * t / (2.0 * a), t / a, 1.0 / a, 0.0};
    }
    const double ab = a * b;
    if (t < b) return {t * t * t / (6.0 * ab), t * t / (2.0 * ab), t / ab, 1.0 / ab};
    if (t < a) {
        const double m = t - 0.5 * b;
        return {m * m / (2.0 * a) + b * b / (24.0 * a), m / a, 1.0 / a, 0.0};
    }
    const double u = td - t;  // symmetric kernel: R(t) = t - Td/2 + R(Td - t)
    return {t - 0.5 * td + u * u * u / (6.0 * ab), 1.0 - u * u / (2.0 * ab), u / ab, -1.0 / ab};
}

// two_stage_step(a, b, t).position, the same arithmetic.
inline double two_stage_position(double a, double b, double t) {
    const double td = a + b;
    if (t >= td) return t - 0.5 * td;
    if (b <= 0.0) return t * t / (2.0 * a);
    const double ab = a * b;
    if (t < b) return t * t * t / (6.0 * ab);
    if (t < a) {
        const double m = t - 0.5 * b;
        return m * m / (2.0 * a) + b * b / (24.0 * a);
    }
    const double u = td - t;
    return t - 0.5 * td + u * u * u / (6.0 * ab);
}

}  // namespace kernel_detail

inline StepSample Kernel::step(double t) const {
    if (chain != nullptr) return chain->step(t);
    if (a <= 0.0) return t >= 0.0 ? StepSample{t, 1.0, 0.0, 0.0} : StepSample{};  // sharp: full speed from t = 0
    if (t <= kernel_detail::started_after) return {};
    return kernel_detail::two_stage_step(a, b, t);
}

inline double Kernel::lead() const {
    if (chain != nullptr) return chain->position(0.5 * chain->delay());
    return a > 0.0 ? (3.0 * a * a + b * b) / (24.0 * a) : 0.0;
}

// Two moving averages of lengths t1 and t2 (any order, >= 0).
inline Kernel two_stage(double t1, double t2) {
    Kernel k;
    k.a = std::max(t1, t2);
    k.b = std::min(t1, t2);
    return k;
}

inline double Kernel::step_position(double t) const {
    if (chain != nullptr) return chain->step(t).position;
    if (a <= 0.0) return t >= 0.0 ? t : 0.0;
    if (t <= kernel_detail::started_after) return 0.0;
    return kernel_detail::two_stage_position(a, b, t);
}

// T1 of a step dV: max over the axes of |dV_a| / A_a (0 for axes without an acceleration limit).
double acceleration_time(const MachineLimits& limits, const AxisVector& dv);

// The fastest two-stage kernel for one step alone (a start from rest or a stop, which share no
// moving average): a step of speed v along a direction whose acceleration time per unit of speed
// is `alpha` (max_a |u_a| / A_a) and whose jerk product per unit of speed is `beta`
// (max_a |u_a| / J_a). Its stages T1 >= T2 keep T1 >= v alpha (acceleration) and T1 T2 >= v beta
// (jerk): T1 = max(v alpha, sqrt(v beta)), T2 = v beta / T1. A small step ramps in and out at the
// jerk limit (T1 = T2, a triangle of acceleration sqrt(J dV)): the jerk-limited S-curve of that step.
// Never wider than two_stage(v alpha, T2_machine) when beta <= alpha T2_machine.
Kernel sized_kernel(double v, double alpha, double beta);

// The kernel of a step dV at `limits` (smoothing_limits: parameters.hpp): two_stage(acceleration_time, jerk_time).
Kernel step_kernel(const MachineLimits& limits, const AxisVector& dv);

}  // namespace firtp
