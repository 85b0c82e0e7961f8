#include <firtp/kernel.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

double Kernel::position(double t) const {
    if (chain != nullptr) return chain->position(t);
    if (t <= 0.0) return 0.0;
    if (a <= 0.0) return t;  // sharp
    return kernel_detail::two_stage_step(a, b, t).position;
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

Kernel sized_kernel(double v, double alpha, double beta) {
    const double t1 = std::max(v * alpha, std::sqrt(v * beta));
    return two_stage(t1, t1 > 0.0 ? v * beta / t1 : 0.0);
}

Kernel step_kernel(const MachineLimits& limits, const AxisVector& dv) {
    return two_stage(acceleration_time(limits, dv), jerk_time(limits));
}

}  // namespace firtp
