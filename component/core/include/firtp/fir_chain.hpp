// The chain of n moving-average filters in closed form.
//
// Principle: the chain is linear and time-invariant, so its response to a train of velocity
// pulses is the sum of its responses to the pulses' edges (velocity steps). The response of the
// chain to a unit velocity step is a piecewise polynomial of degree n + 1 in time with knots at
// the sums of subsets of {T1..Tn}; it is computed once when the filter times are set and then
// evaluated at any real time. Time constants and pulse edges need not fall on servo samples: the
// samples are the continuous-time filter output taken at t = k * period, exactly.
#pragma once

#include <firtp/parameters.hpp>

#include <array>

namespace firtp {

// Value and derivatives of the chain's response to a unit velocity step at t = 0.
struct StepSample {
    double position = 0.0;      // R(t): integral of the step response
    double velocity = 0.0;      // Sigma(t): 0 -> 1 over [0, Td]
    double acceleration = 0.0;  // Sigma'(t): the chain's impulse response
    double jerk = 0.0;          // Sigma''(t)
};

class FirChain {
public:
    FirChain() = default;
    explicit FirChain(const FilterTimes& filters);

    const FilterTimes& filters() const { return filters_; }
    double delay() const { return delay_; }  // Td (Eq. 6)

    // R(t) = 0 for t <= 0 and t - Td/2 for t >= Td.
    StepSample step(double t) const;
    double position(double t) const;  // R(t) alone

    // Normalised progress of one block whose velocity pulse has width tv and starts at t = 0:
    // S(t) = (R(t) - R(t - tv)) / tv, from 0 to 1 over [0, tv + Td]; derivatives likewise.
    StepSample pulse(double t, double tv) const;
    double pulse_position(double t, double tv) const { return (position(t) - position(t - tv)) / tv; }

private:
    static constexpr int max_pieces = 1 << max_stages;
    static constexpr int max_degree = max_stages + 1;

    FilterTimes filters_{};
    double delay_ = 0.0;
    int pieces_ = 0;
    int degree_ = 0;
    std::array<double, max_pieces + 1> knots_{};                            // 0 = k0 < ... < k_m = Td
    std::array<std::array<double, max_degree + 1>, max_pieces> coeff_{};  // R on piece i in (t - knot_i)
};

}  // namespace firtp
