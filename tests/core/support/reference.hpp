// Independent references for the FIR chain, written differently from the core:
// - box_spline_progress: the chain's response to one pulse from the truncated-power formula of
//   the convolution of n + 1 boxes, in quadruple precision (no piecewise tables).
// - simulate_discrete_fir: moving averages as running sums on a fine grid, as in the paper's
//   "chain of FIR filters" (Fig. 2), for geometric checks.
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <cmath>
#include <vector>

namespace firtp::test {

__extension__ typedef __float128 quad;  // the truncated powers cancel heavily: 113-bit mantissa

// Normalised position S(t) in [0, 1] of a pulse of width tv through the chain.
inline double box_spline_progress(const FilterTimes& f, double tv, double t) {
    const int n = f.stages;
    quad w[max_stages + 1] = {tv};
    quad scale = tv;
    for (int i = 0; i < n; ++i) w[i + 1] = f.T[i], scale *= f.T[i];
    for (int k = 2; k <= n + 1; ++k) scale *= k;
    quad sum = 0;
    for (int j = 0; j < (1 << (n + 1)); ++j) {
        quad x = t;
        int sign = 1;
        for (int i = 0; i <= n; ++i)
            if (j & (1 << i)) x -= w[i], sign = -sign;
        if (x <= 0) continue;
        quad power = 1;
        for (int k = 0; k <= n; ++k) power *= x;
        sum += sign * power;
    }
    return static_cast<double>(sum / scale);
}

struct Pulse {
    AxisVector delta;
    double start;  // s
    double tv;     // s
};

// Position of the sum of pulses through the chain, at t: exact (long double) reference.
inline AxisVector reference_position(const FilterTimes& f, const AxisVector& start,
                                     const std::vector<Pulse>& pulses, double t) {
    AxisVector p = start;
    for (const Pulse& q : pulses) {
        const double s = box_spline_progress(f, q.tv, t - q.start);
        p += q.delta * (t - q.start >= q.tv + f.delay() ? 1.0 : s);
    }
    return p;
}

// Running-sum FIR chain on a grid of dt (every T_i must be a whole number of dt). Returns the
// position at k * dt for k = 0 .. steps.
inline std::vector<AxisVector> simulate_discrete_fir(const FilterTimes& f, const AxisVector& start,
                                                     const std::vector<Pulse>& pulses, double dt, int steps) {
    std::vector<AxisVector> v(steps, AxisVector::Zero());
    for (const Pulse& q : pulses) {  // cell averages of the velocity pulses
        const AxisVector rate = q.delta / q.tv;
        for (int k = 0; k < steps; ++k) {
            const double a = std::max(k * dt, q.start), b = std::min((k + 1) * dt, q.start + q.tv);
            if (b > a) v[k] += rate * ((b - a) / dt);
        }
    }
    for (int i = 0; i < f.stages; ++i) {
        const int w = static_cast<int>(std::lround(f.T[i] / dt));
        std::vector<AxisVector> out(steps, AxisVector::Zero());
        Eigen::Matrix<long double, max_axes, 1> sum = Eigen::Matrix<long double, max_axes, 1>::Zero();
        for (int k = 0; k < steps; ++k) {
            sum += v[k].cast<long double>();
            if (k >= w) sum -= v[k - w].cast<long double>();
            out[k] = (sum / static_cast<long double>(w)).cast<double>();
        }
        v.swap(out);
    }
    std::vector<AxisVector> p(steps + 1, start);
    for (int k = 0; k < steps; ++k) p[k + 1] = p[k] + v[k] * dt;
    return p;
}

inline FilterTimes chain_of(std::initializer_list<double> times) {
    FilterTimes f;
    f.stages = static_cast<int>(times.size());
    int i = 0;
    for (double t : times) f.T[i++] = t;
    return f;
}

// A G01 block to `target`.
inline Block line_to(const AxisVector& target, double feed, double tolerance, std::int64_t line,
                     Termination termination = Termination::blend) {
    Block b;
    b.target = target;
    b.feed = feed;
    b.tolerance = tolerance;
    b.termination = termination;
    b.line = line;
    return b;
}

inline AxisVector xyz(double x, double y, double z = 0.0) {
    AxisVector v = AxisVector::Zero();
    v << x, y, z, 0, 0, 0, 0, 0, 0;
    return v;
}

}  // namespace firtp::test
