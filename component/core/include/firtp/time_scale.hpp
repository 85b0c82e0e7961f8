// Feed override, hold and abort as time scaling: the filters' clock advances by rate * period each
// servo period, so the tool stays on the planned path at any rate. The rate follows its target
// with a bounded slope (full scale in `ramp_time`), so speed changes are continuous.
#pragma once

namespace firtp {

class TimeScale {
public:
    explicit TimeScale(double ramp_time = 0.2) : ramp_time_(ramp_time) {}

    void set_target(double rate) { target_ = rate < 0.0 ? 0.0 : rate; }
    double target() const { return target_; }
    double rate() const { return rate_; }
    double slope() const { return slope_; }  // d rate / dt over the last period, 1/s
    bool stopped() const { return rate_ == 0.0 && target_ == 0.0; }

    // Nothing moves: take the target at once.
    void snap() {
        rate_ = target_;
        slope_ = 0.0;
    }

    // One servo period: returns how far the filters' clock moves, in periods.
    double advance(double period) {
        const double step = ramp_time_ > 0.0 ? period / ramp_time_ : 1e300;
        const double before = rate_;
        if (rate_ < target_) rate_ = rate_ + step < target_ ? rate_ + step : target_;
        else if (rate_ > target_) rate_ = rate_ - step > target_ ? rate_ - step : target_;
        slope_ = (rate_ - before) / period;
        return 0.5 * (before + rate_);  // exact for a linear ramp
    }

private:
    double ramp_time_;
    double target_ = 1.0;
    double rate_ = 1.0;
    double slope_ = 0.0;
};

}  // namespace firtp
