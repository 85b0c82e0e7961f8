#include <firtp/kernel.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

namespace {

// A kernel starting within this of the sample has not started: where one step ends a leg and starts
// the next, the two legs' clocks may round to either side of it, and a sample would see half the
// step's jerk (its motion so far, ~J t^3 / 6, is nothing).
constexpr double started_after = 1e-9;  // s

// R(t) of two moving averages a >= b > 0 (the integral of the step response): a cubic ramp-in,
// a parabola, a cubic ramp-out; R(t) = t - (a + b) / 2 beyond.
StepSample two_stage_step(double a, double b, double t) {
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
double two_stage_position(double a, double b, double t) {
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

}  // namespace

Kernel two_stage(double t1, double t2) {
    Kernel k;
    k.a = std::max(t1, t2);
    k.b = std::min(t1, t2);
    return k;
}

StepSample Kernel::step(double t) const {
    if (chain != nullptr) return chain->step(t);
    if (a <= 0.0) return t >= 0.0 ? StepSample{t, 1.0, 0.0, 0.0} : StepSample{};  // sharp: full speed from t = 0
    if (t <= started_after) return {};
    return two_stage_step(a, b, t);
}

double Kernel::step_position(double t) const {
    if (chain != nullptr) return chain->step(t).position;
    if (a <= 0.0) return t >= 0.0 ? t : 0.0;
    if (t <= started_after) return 0.0;
    return two_stage_position(a, b, t);
}

double Kernel::position(double t) const {
    if (chain != nullptr) return chain->position(t);
    if (t <= 0.0) return 0.0;
    if (a <= 0.0) return t;  // sharp
    return two_stage_step(a, b, t).position;
}

double Kernel::lead() const {
    if (chain != nullptr) return chain->position(0.5 * chain->delay());
    return a > 0.0 ? (3.0 * a * a + b * b) / (24.0 * a) : 0.0;
}

double Kernel::lead_at(double offset) const {
    const double d = std::abs(offset), half = 0.5 * width();
    if (d >= half) return 0.0;
    return position(half + d) - d;
}

double Kernel::peak_acceleration() const {
    if (chain != nullptr) return 1.0 / chain->filters().T[0];
    return a > 0.0 ? 1.0 / a : std::numeric_limits<double>::infinity();
}

double Kernel::peak_jerk() const {
    if (chain != nullptr)
        return chain->filters().stages > 1 ? 1.0 / (chain->filters().T[0] * chain->filters().T[1])
                                           : std::numeric_limits<double>::infinity();
    return b > 0.0 ? 1.0 / (a * b) : std::numeric_limits<double>::infinity();
}

double acceleration_time(const MachineLimits& limits, const AxisVector& dv) {
    double t = 0.0;
    for (int i = 0; i < limits.axes; ++i) {
        const double acc = limits.axis[i].max_acceleration;
        if (acc > 0.0) t = std::max(t, std::abs(dv[i]) / acc);
    }
    return t;
}

Kernel step_kernel(const MachineLimits& limits, const AxisVector& dv) {
    return two_stage(acceleration_time(limits, dv), jerk_time(limits));
}

}  // namespace firtp
