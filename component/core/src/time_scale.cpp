#include <firtp/time_scale.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace firtp {

RateLimits rate_limits(const PlannerParameters& parameters) {
    // Per axis, with p' <= V_p, p'' <= A_p planned and the rate at most M:
    //   a: r' V_p <= reserve A;   j: 3 M r' A_p <= reserve J / 2,  r'' V_p <= reserve J - 3 M r' A_p.
    const MachineLimits planned = planned_limits(parameters);
    const double m = std::max(parameters.max_rate, 1.0), reserve = parameters.rate_reserve;
    double slope = HUGE_VAL;
    for (int i = 0; i < parameters.limits.axes; ++i) {
        const AxisLimits& l = parameters.limits.axis[i];
        const AxisLimits& p = planned.axis[i];
        if (p.max_velocity > 0.0 && l.max_acceleration > 0.0) slope = std::min(slope, reserve * l.max_acceleration / p.max_velocity);
        if (p.max_acceleration > 0.0 && l.max_jerk > 0.0)
            slope = std::min(slope, reserve * l.max_jerk / (6.0 * m * p.max_acceleration));
    }
    if (!std::isfinite(slope)) return RateLimits{};
    double curvature = HUGE_VAL;
    for (int i = 0; i < parameters.limits.axes; ++i) {
        const AxisLimits& l = parameters.limits.axis[i];
        const AxisLimits& p = planned.axis[i];
        if (p.max_velocity > 0.0 && l.max_jerk > 0.0)
            curvature = std::min(curvature, (reserve * l.max_jerk - 3.0 * m * slope * p.max_acceleration) / p.max_velocity);
    }
    RateLimits limits{slope, std::isfinite(curvature) ? curvature : RateLimits{}.max_curvature * slope / RateLimits{}.max_slope};
    return limits;
}

double stop_time(const RateLimits& limits, double from) {
    // From rest at `from`: at most from / r' + r' / r'' (AM-GM covers ramps that never reach r').
    // A rate still rising first needs r' / r'' to turn, never passing its target.
    if (from <= 0.0) return 0.0;
    return from / limits.max_slope + 2.0 * limits.max_slope / limits.max_curvature;
}

namespace {

// Rate covered while the slope v > 0 falls by `reach` a period to 0 (trapezoids, as advance()).
double braking_distance(double v, double reach, double period) {
    if (v <= 0.0) return 0.0;
    const double m = std::ceil(v / reach);
    return period * (m * v - reach * m * (m - 1.0) / 2.0 - 0.5 * v);
}

}  // namespace

void TimeScale::trim(double periods, double period) {
    if (!(periods > 0.0 && periods < 1.0)) return;
    // Sum of the trapezoids over N periods: N - c N / 2. Peaks: r' = c pi / (N T), r'' = 2 c pi^2 / (N T)^2.
    constexpr double pi = std::numbers::pi;
    const double by_slope = std::sqrt(4.0 * pi * periods / (period * limits_.max_slope));
    const double by_curvature = std::cbrt(8.0 * pi * pi * periods / (period * period * limits_.max_curvature));
    trim_ticks_ = static_cast<int>(std::min(std::ceil(std::max({by_slope, by_curvature, 8.0})), 1e6));
    trim_step_ = 0;
    trim_depth_ = 2.0 * periods / trim_ticks_;
}

double TimeScale::advance(double period) {
    const double before = rate_, slope_before = slope_;
    if (trim_ticks_ > 0) {
        if (target_ == 1.0) {
            const double x = std::numbers::pi * ++trim_step_ / trim_ticks_;
            rate_ = 1.0 - trim_depth_ * std::sin(x) * std::sin(x);
            slope_ = -trim_depth_ * std::numbers::pi / (trim_ticks_ * period) * std::sin(2.0 * x);
            if (trim_step_ == trim_ticks_) {
                rate_ = 1.0;
                slope_ = 0.0;
                trim_ticks_ = 0;
            }
            curvature_ = (slope_ - slope_before) / period;
            return 0.5 * (before + rate_);
        }
        trim_ticks_ = 0;  // a new target: the S-curve goes on from this rate and slope
    }
    const double gap = target_ - rate_;
    if (gap == 0.0 && slope_ == 0.0) {
        curvature_ = 0.0;
        return rate_;
    }
    // In the direction of the target: the fastest slope this period that can still brake, a
    // period at a time, without passing it.
    const double sign = gap > 0.0 ? 1.0 : -1.0, distance = std::abs(gap), slope = slope_ * sign;
    const double reach = limits_.max_curvature * period;
    const double lo = std::max(slope - reach, -limits_.max_slope), hi = std::min(slope + reach, limits_.max_slope);
    auto step = [&](double x) { return 0.5 * (slope + x) * period; };
    auto stops_in_time = [&](double x) { return x <= 0.0 || distance - step(x) >= braking_distance(x, reach, period); };
    double next = lo;
    if (stops_in_time(hi)) {
        next = hi;
    } else if (stops_in_time(lo)) {
        double a = lo, b = hi;
        for (int i = 0; i < 48; ++i) (stops_in_time(0.5 * (a + b)) ? a : b) = 0.5 * (a + b);
        next = a;
    }
    // Lands on the target: what is left is below 1e-9 of the rate (the bisection's leftovers would
    // otherwise halve period after period), and the slope can stop within one period.
    if (std::abs(slope) <= reach && std::abs(next) <= reach && distance - step(next) <= 1e-9) {
        rate_ = target_;
        slope_ = 0.0;
    } else {
        slope_ = next * sign;
        rate_ = std::max(rate_ + step(next) * sign, 0.0);
    }
    curvature_ = (slope_ - slope_before) / period;
    return 0.5 * (before + rate_);
}

}  // namespace firtp
