#include <firtp/junction.hpp>

#include <firtp/kernel.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double reversal_sine = 1.0 - 1e-12;  // s = sin(beta / 2) this close to 1: the path turns back

// The real root of v^3 + p v + q = 0 for p > 0 (one real root), Cardano polished by Newton.
double depressed_cubic_root(double p, double q) {
    const double root = std::sqrt(0.25 * q * q + p * p * p / 27.0);
    double v = std::cbrt(-0.5 * q + root) + std::cbrt(-0.5 * q - root);
    for (int i = 0; i < 3; ++i) v -= (v * v * v + p * v + q) / (3.0 * v * v + p);  // the sum cancels when p dominates
    return v;
}
}  // namespace

Turn make_turn(const AxisVector& u_in, const AxisVector& u_out, const MachineLimits& limits) {
    Turn t;
    t.du = u_out - u_in;
    const double n = t.du.norm();
    if (n > 0.0) t.direction = t.du / n;
    t.beta = 2.0 * std::atan2(t.du.norm(), (u_in + u_out).norm());
    t.s = std::sin(0.5 * t.beta);
    for (int i = 0; i < limits.axes; ++i) {
        const double acc = limits.axis[i].max_acceleration;
        if (acc > 0.0) t.alpha = std::max(t.alpha, std::abs(t.du[i]) / acc);
    }
    t.reversal = t.s >= reversal_sine;
    return t;
}

double corner_speed(double alpha, double t2, double s, double epsilon) {
    if (!(s > 0.0) || !(alpha > 0.0) || t2 < 0.0) return infinity;
    if (!(epsilon > 0.0)) return 0.0;
    const double r = epsilon / s;  // err / s
    if (t2 <= 0.0) return std::sqrt(4.0 * r / alpha);  // one stage: err = s V^2 alpha / 4
    // V alpha >= t2: err / s = (3 V^2 alpha^2 + t2^2) / (12 alpha).
    const double square = (12.0 * alpha * r - t2 * t2) / (3.0 * alpha * alpha);
    if (square > 0.0 && std::sqrt(square) * alpha >= t2) return std::sqrt(square);
    // V alpha < t2: err / s = V (3 t2^2 + V^2 alpha^2) / (12 t2), increasing in V; Cardano for
    // V^3 + p V + q = 0 with p > 0 (one real root).
    return depressed_cubic_root(3.0 * t2 * t2 / (alpha * alpha), -12.0 * t2 * r / (alpha * alpha));
}

double chord_margin(double acceleration, double jerk, double period) {
    return (acceleration + std::min(jerk * period, 2.0 * acceleration)) * period * period / 8.0;
}

double sampled_corner_speed(double alpha, double t2, double s, double du, double jerk, double period, double epsilon) {
    double hi = corner_speed(alpha, t2, s, epsilon);  // without the chords: an upper bound
    if (!std::isfinite(hi) || !(hi > 0.0)) return hi;
    auto error = [&](double v) {
        const double t1 = v * alpha;
        const double peak = t1 > 0.0 ? v * du / std::max(t1, t2) : 0.0;  // the step's largest acceleration
        return 2.0 * s * v * two_stage(t1, t2).lead() + chord_margin(peak, jerk, period);
    };
    if (error(hi) <= epsilon) return hi;
    // error(v) grows with v, in closed form piece by piece. V alpha >= t2: the peak is |du| / alpha,
    // and s (3 V^2 alpha^2 + t2^2) / (12 alpha) + margin(|du| / alpha) = epsilon is a square.
    // V alpha < t2: the peak V |du| / t2 is linear in V, the margin (peak + min(J T, 2 peak)) T^2 / 8
    // too on either side of the peak J T / 2: s V (3 t2^2 + V^2 alpha^2) / (12 t2) + margin = epsilon
    // is a cubic without a square term.
    const double p2 = period * period;
    const double v_box = t2 / alpha;  // T1 = t2
    double v = 0.0;
    if (!(t2 > 0.0) || error(v_box) <= epsilon) {
        const double rest = epsilon - chord_margin(du / alpha, jerk, period);
        v = std::sqrt(std::max(0.0, (12.0 * alpha * rest / s - t2 * t2) / (3.0 * alpha * alpha)));
    } else {
        const double v_kink = du > 0.0 ? 0.5 * jerk * period * t2 / du : infinity;  // 2 peak = J T
        const bool above_kink = v_kink < v_box && error(v_kink) <= epsilon;
        const double c3 = s * alpha * alpha / (12.0 * t2);
        const double c1 = 0.25 * s * t2 + (above_kink ? 1.0 : 3.0) * p2 * du / (8.0 * t2);
        const double c0 = above_kink ? jerk * period * p2 / 8.0 : 0.0;
        v = depressed_cubic_root(c1 / c3, (c0 - epsilon) / c3);
    }
    v = std::min(v, hi);
    // Rounding may put the root a few ulps past epsilon: step down onto the safe side.
    for (int i = 0; i < 8 && error(v) > epsilon; ++i) v *= 1.0 - 4e-16 * static_cast<double>(1 << (3 * i));
    if (v == 0.0 || error(v) <= epsilon) return v;  // (0: the margin alone is more than epsilon)
    double lo = 0.0;  // (not reached on finite inputs; bisection as the last word)
    for (int i = 0; i < 50 && hi - lo > 1e-9 * hi; ++i) (error(0.5 * (lo + hi)) <= epsilon ? lo : hi) = 0.5 * (lo + hi);
    return lo;
}

}  // namespace firtp
