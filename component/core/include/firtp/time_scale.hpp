// Feed override, hold and abort as time scaling: the filters' clock advances by rate * period each
// servo period, so the tool stays on the planned path at any rate. The rate follows its target
// along an S-curve: its slope r' and the slope's change r'' are bounded (RateLimits), so the
// axes see, by the chain rule, v = r p', a = r^2 p'' + r' p', j = r^3 p''' + 3 r r' p'' + r'' p'.
#pragma once

#include <firtp/parameters.hpp>

namespace firtp {

struct RateLimits {
    double max_slope = 5.0;         // |r'|, 1/s (full rate in 0.2 s)
    double max_curvature = 100.0;   // |r''|, 1/s^2
};

// The fastest ramps that keep the axis limits when the plan used only planned_limits(): the ramp
// terms r' p' and 3 r r' p'' + r'' p' fit in the reserve r of acceleration and jerk, with p' and
// p'' at their planned maxima. Without axis limits: the defaults above.
RateLimits rate_limits(const PlannerParameters& parameters);

// The longest a hold or abort takes to bring a rate of at most `from` to rest, rising or not.
double stop_time(const RateLimits& limits, double from);

class TimeScale {
public:
    explicit TimeScale(const RateLimits& limits = {}) : limits_(limits) {}

    void set_target(double rate) { target_ = rate < 0.0 ? 0.0 : rate; }
    double target() const { return target_; }
    double rate() const { return rate_; }
    double slope() const { return slope_; }          // r' at the end of the last period, 1/s
    double curvature() const { return curvature_; }  // r'' over the last period, 1/s^2
    bool stopped() const { return rate_ == 0.0 && target_ == 0.0; }
    const RateLimits& limits() const { return limits_; }

    // Nothing moves: take the target at once.
    void snap() {
        rate_ = target_;
        slope_ = 0.0;
        curvature_ = 0.0;
        trim_ticks_ = 0;
    }

    // At rate 1 after a ramp, lose `periods` (0..1) of the clock along a smooth dip of the rate,
    // 1 - c sin^2(pi k / N), within half the rate limits: the servo samples come back onto the
    // planned sample grid, whose polyline the planner checked. A new target ends it.
    void trim(double periods, double period);
    bool steady_at_one() const { return rate_ == 1.0 && target_ == 1.0 && slope_ == 0.0 && trim_ticks_ == 0; }

    // One servo period: returns how far the filters' clock moves, in periods (exactly 1 at rate 1).
    double advance(double period);

private:
    RateLimits limits_;
    double target_ = 1.0;
    double rate_ = 1.0;
    double slope_ = 0.0;
    double curvature_ = 0.0;
    int trim_ticks_ = 0;  // N, 0: no trim
    int trim_step_ = 0;
    double trim_depth_ = 0.0;  // c = 2 periods / N
};

}  // namespace firtp
