// What a lightly damped structural mode does under a sampled trajectory: the base-excited
// oscillator x'' + 2 zeta w x' + w^2 x = -a(t), a = one axis's commanded acceleration, integrated
// exactly from sample to sample. Like measure.hpp it uses the samples only, so it compares any
// planners.
#pragma once

#include <firtp/types.hpp>

#include <span>
#include <vector>

namespace firtp {

struct ModeResponse {
    std::vector<double> deflection;  // x at every sample (units of the axis): the tool's lag behind the command
    std::vector<double> vibration;   // amplitude of the oscillation at every sample (see below)

    struct Stop {
        std::size_t sample = 0;
        double time = 0.0;
        double amplitude = 0.0;  // residual vibration: amplitude of the free oscillation left at rest
    };
    std::vector<Stop> stops;            // every sample where the machine comes to rest (the last one included)
    double max_stop_residual = 0.0;     // the largest amplitude at a stop
    double final_residual = 0.0;        // amplitude at the last sample
    double max_moving_vibration = 0.0;  // the largest oscillation amplitude while moving (corners, ramps)
    double max_moving_deflection = 0.0; // the largest |x| while moving (lag from acceleration plus oscillation)
};

// Simulates one mode on `axis`. Between samples the acceleration is the cubic that matches the
// sampled acceleration and jerk at both ends (exact for piecewise polynomials of degree <= 3 whose
// knots fall on samples: up to four FIR stages, the S-curve at its breakpoints) and the
// oscillator is advanced with the exact discretisation for that input (matrix exponential).
//
// The oscillation amplitude separates the lag that the acceleration itself causes: with
// x_q = -(a - 2 zeta j / w) / w^2 (the exact forced response while the jerk is constant) and
// e = x - x_q, the amplitude is sqrt(e^2 + ((e' + zeta w e) / w_d)^2). At rest it is the residual
// vibration; while moving it is exact where the acceleration is piecewise linear (one or two FIR
// stages, the S-curve), an estimate otherwise (the a'' term is left out).
//
// Rest: every axis has |v| and |a| below 1e-9. Samples must be spaced by `period`.
ModeResponse simulate_mode(std::span<const AxisState> samples, int axis, double frequency_hz, double damping,
                           double period);

// |sum_k a_k exp(-j 2 pi f t_k)| * period: the spectrum of one axis's sampled acceleration
// (units/s), at each frequency asked for (Eq. 9: the chain's magnitude shapes it).
std::vector<double> acceleration_spectrum(std::span<const AxisState> samples, int axis,
                                          std::span<const double> frequencies_hz);

}  // namespace firtp
