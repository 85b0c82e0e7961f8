#include <firtp/corner.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace firtp {

namespace {

constexpr int grid_points = 8;
constexpr int refine_steps = 16;  // brackets shrink to 0.618^16 = 5e-4 of a grid step (a coarser t* only makes Tk smaller)
constexpr int phase_grid = 8;     // sampling phase: grid of 1/8 period,
// then 0.618^40 = 4e-9 of a grid step: where the worst phase is a kink (a reversal: the nearer of
// two samples), the value found falls short of it linearly in the step (at 12 steps, 1.4e-5 of eps
// on seed 23 program 3032 of RandomPaths.SpatialCornerPointTolerance, beyond phase_margin)
constexpr int phase_steps = 40;
constexpr double golden = 0.6180339887498949;
constexpr double phase_margin = 1e-5;  // of epsilon, for maxima found by search (sampling phase, contour)
constexpr double overlap_resolution = 5e-7;  // s; Tk is rounded down to this

// Golden-section search for the extremum of a unimodal f over [lo, hi]; sign = +1 minimum, -1
// maximum. Returns {argument, value} of the best point evaluated.
template <class F>
std::pair<double, double> golden_section(F&& f, double lo, double hi, double sign, int steps) {
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    double f1 = sign * f(x1), f2 = sign * f(x2);
    for (int i = 0; i < steps; ++i) {
        if (f1 < f2) {
            hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = sign * f(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = sign * f(x2);
        }
    }
    return f1 < f2 ? std::pair{x1, sign * f1} : std::pair{x2, sign * f2};
}

// Extremum of f over [a, b]: coarse grid (f need not be unimodal), then golden section around
// the best grid point. sign = +1 finds the minimum, -1 the maximum. Returns {argument, value}.
template <class F>
std::pair<double, double> extremum(F&& f, double a, double b, double sign, int grid = grid_points,
                                   int refine = refine_steps) {
    if (b <= a) return {a, f(a)};
    const double step = (b - a) / grid;
    double best_t = a, best = sign * f(a);
    for (int i = 1; i <= grid; ++i) {
        const double t = a + step * i;
        if (const double v = sign * f(t); v < best) best = v, best_t = t;
    }
    const auto [t, v] = golden_section(f, std::max(a, best_t - step), std::min(b, best_t + step), sign, refine);
    return sign * v < best ? std::pair{t, v} : std::pair{best_t, sign * best};
}

double distance_to_segment(const AxisVector& p, const AxisVector& a, const AxisVector& b) {
    const AxisVector ab = b - a;
    const double len2 = ab.squaredNorm();
    const double u = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - a - u * ab).norm();
}

// Largest Tk in [0, Tk_max] with error(Tk) <= epsilon, keeping error(lo) <= epsilon throughout.
// Tk = 0 always holds: the planner then rests on the corner for at least one sample. False
// position with the Illinois modification: a handful of error evaluations instead of ~20.
template <class E>
double bisect_overlap(E&& error, double epsilon, double Tk_max) {
    double hi = Tk_max, f_hi = error(Tk_max) - epsilon;
    if (f_hi <= 0.0) return Tk_max;
    double lo = 0.0, f_lo = -epsilon;
    int side = 0;
    for (int i = 0; i < 60 && hi - lo > overlap_resolution; ++i) {
        double mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
        const double f_mid = error(mid) - epsilon;
        if (f_mid <= 0.0) {
            lo = mid, f_lo = f_mid;
            if (side == -1) f_hi *= 0.5;
            side = -1;
        } else {
            hi = mid, f_hi = f_mid;
            if (side == 1) f_lo *= 0.5;
            side = 1;
        }
    }
    return lo;
}

}  // namespace

AxisVector CornerModel::offset(double t, double Tk) const {
    const double s_in = chain->pulse_position(t + in_tv, in_tv);
    const double s_out = chain->pulse_position(t - (chain->delay() - Tk), out_tv);
    return out_delta * s_out - in_delta * (1.0 - s_in);
}

double CornerModel::corner_error(double Tk) const {
    const double td = chain->delay();
    return extremum([&](double t) { return offset(t, Tk).norm(); }, td - Tk, td, 1.0).second;
}

double CornerModel::sampled_corner_error(double Tk, double period) const {
    const double td = chain->delay();
    const double t = extremum([&](double x) { return offset(x, Tk).norm(); }, td - Tk, td, 1.0).first;
    const AxisVector corner = AxisVector::Zero();
    auto chord = [&](double phase) {
        const double a = t - phase * period;
        return distance_to_segment(corner, offset(a, Tk), offset(a + period, Tk));
    };
    // Not unimodal when the overlap is shorter than a period (the nearest point of the chord
    // jumps to an end): grid first, then refine.
    return extremum(chord, 0.0, 1.0, -1.0, phase_grid, phase_steps).second;
}

double CornerModel::contour_error(double Tk) const {
    const double td = chain->delay();
    const AxisVector origin = AxisVector::Zero();
    const AxisVector from = -in_delta;
    auto distance = [&](double t) {
        const AxisVector p = offset(t, Tk);
        return std::min(distance_to_segment(p, from, origin), distance_to_segment(p, origin, out_delta));
    };
    // A maximum: a coarse search would under-report it, so search finely.
    return extremum(distance, td - Tk, td, -1.0, 4 * grid_points, 2 * refine_steps).second;
}

double turn_angle(const AxisVector& in_delta, const AxisVector& out_delta) {
    const AxisVector a = in_delta.normalized(), b = out_delta.normalized();
    return 2.0 * std::atan2((a - b).norm(), (a + b).norm());
}

double solve_overlap(const CornerModel& corner, double epsilon, ToleranceMeaning meaning, double period,
                     double Tk_max) {
    if (Tk_max <= 0.0) return 0.0;
    if (std::isinf(epsilon)) return Tk_max;
    const double f_in = corner.in_delta.norm() / corner.in_tv;
    const double f_out = corner.out_delta.norm() / corner.out_tv;
    const double short_pulse = std::min(corner.in_tv, corner.out_tv);
    if (meaning == ToleranceMeaning::corner_point && std::abs(f_in - f_out) <= 1e-12 * f_in) {
        // Closest approach at the middle of the overlap, 2 F s R(Tk / 2) (Eq. 13/14 for any
        // chain). Worst sampling phase: samples half a period either side, whose chord lies
        // F s (R(Tk/2 - Ts/2) + R(Tk/2 + Ts/2)) from the corner.
        const double s = std::sin(0.5 * turn_angle(corner.in_delta, corner.out_delta));
        const FirChain& chain = *corner.chain;
        auto error = [&](double Tk) {
            return f_in * s * (chain.position(0.5 * (Tk - period)) + chain.position(0.5 * (Tk + period)));
        };
        // The closed form holds while neither pulse ends inside the overlap.
        const double cap = std::min(Tk_max, short_pulse);
        const double Tk = bisect_overlap(error, epsilon, cap);
        if (Tk < cap || cap == Tk_max) return Tk;
    }
    if (meaning == ToleranceMeaning::corner_point)  // the phase maximum is found to ~1e-6: keep 1e-5 of eps
        return bisect_overlap([&](double Tk) { return corner.sampled_corner_error(Tk, period); },
                              epsilon * (1.0 - phase_margin), Tk_max);
    return bisect_overlap([&](double Tk) { return corner.contour_error(Tk); }, epsilon * (1.0 - phase_margin), Tk_max);
}

}  // namespace firtp
