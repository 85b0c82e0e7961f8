#include <firtp/braking.hpp>

#include <algorithm>
#include <cmath>

namespace firtp {

BrakingPeaks braking_peaks(const FirChain& chain) {
    constexpr int samples = 1 << 16;
    const double td = chain.delay();
    BrakingPeaks peaks;
    for (int k = 1; k < samples; ++k) {
        const StepSample s = chain.step(td * k / samples);
        peaks.acceleration = std::max(peaks.acceleration, std::abs(s.acceleration));
        peaks.jerk = std::max(peaks.jerk, std::abs(s.jerk));
    }
    // The extremes lie on knots (sums of T1..Tn) or between samples: a margin of 1e-6 covers the
    // sampling error of these low-degree pieces.
    peaks.acceleration *= 1.0 + 1e-6;
    peaks.jerk *= 1.0 + 1e-6;
    return peaks;
}

double braking_share(const BrakingPeaks& peaks, const MachineLimits& limits, const AxisVector& velocity) {
    double share = 1.0;
    auto bound = [&share](double limit, double needed) {
        if (limit > 0.0 && needed > limit) share = std::min(share, limit / needed);
    };
    for (int a = 0; a < limits.axes && a < max_axes; ++a) {
        const double v = std::abs(velocity[a]);
        if (!(v > 0.0)) continue;
        const AxisLimits& l = limits.axis[a];
        bound(l.max_velocity, v);
        bound(l.max_acceleration, v * peaks.acceleration);
        bound(l.max_jerk, v * peaks.jerk);
    }
    return share;
}

}  // namespace firtp
