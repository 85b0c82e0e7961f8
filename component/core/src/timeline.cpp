#include <firtp/timeline.hpp>

#include <cmath>

namespace firtp {

void normalise(std::int64_t& tick, double& offset, double period) {
    const double whole = std::floor(offset / period);
    tick += static_cast<std::int64_t>(whole);
    offset -= whole * period;
    if (offset >= period) offset -= period, ++tick;
    if (offset < 0.0) offset = 0.0;
}

StepSample Leg::progress(double t) const {
    if (!(tv > 0.0)) return {};  // a leg of no time (two steps at one instant) moves nothing
    const StepSample up = rising.step(t);
    const StepSample down = falling.step(t - fall);
    return {(up.position - down.position) / tv, (up.velocity - down.velocity) / tv,
            (up.acceleration - down.acceleration) / tv, (up.jerk - down.jerk) / tv};
}

Timeline::Timeline(double period, std::size_t capacity, const AxisVector& start, double max_width,
                   const RateLimits& rates)
    : period_(period), max_width_(max_width), ring_(capacity), base_(start), scale_(rates) {}

void Timeline::reset(const AxisVector& position) {
    head_ = 0;
    count_ = 0;
    base_ = position;
    line_ = 0;
    aborting_ = false;
    flushed_ = false;
}

bool Timeline::push(const Leg& leg) {
    if (count_ == ring_.size()) return false;
    ring_[(head_ + count_) % ring_.size()] = leg;
    ++count_;
    return true;
}

void Timeline::tick(AxisState& out) {
    // Retire legs whose falling kernel has passed: their end point becomes the rest position, exactly.
    while (count_ > 0) {
        const Leg& front = ring_[head_];
        if (clock_time(front) < front.finish()) break;
        base_ = front.end;
        if (front.last_of_block) ++blocks_retired_;
        head_ = (head_ + 1) % ring_.size();
        --count_;
        ++retired_;
    }
    AxisVector velocity = AxisVector::Zero(), acceleration = AxisVector::Zero(), jerk = AxisVector::Zero();
    out.time = static_cast<double>(ticks_) * period_;
    out.position = base_;
    for (std::size_t i = 0; i < count_; ++i) {
        const Leg& leg = at(i);
        const double t = clock_time(leg);
        if (beyond(leg, t)) break;
        const StepSample s = leg.progress(t);
        out.position += leg.delta * s.position;
        velocity += leg.delta * s.velocity;
        acceleration += leg.delta * s.acceleration;
        jerk += leg.delta * s.jerk;
        if (t > 0.0) line_ = leg.line;  // the newest leg in motion
    }
    // Chain rule for the scaled clock (rate r, r', r''): v = r p', a = r^2 p'' + r' p',
    // j = r^3 p''' + 3 r r' p'' + r'' p'.
    const double r = scale_.rate(), dr = scale_.slope(), ddr = scale_.curvature();
    out.velocity = r * velocity;
    out.acceleration = r * r * acceleration + dr * velocity;
    out.jerk = r * r * r * jerk + 3.0 * r * dr * acceleration + ddr * velocity;
    if (count_ == 0) line_ = 0;
    out.line = line_;

    if (aborting_ && scale_.stopped()) {  // at rest on the path: drop the rest of the program
        base_ = out.position;
        head_ = 0;
        count_ = 0;
        line_ = 0;
        aborting_ = false;
        flushed_ = true;
    }
    ++ticks_;
    const bool moving = count_ > 0 && clock_time(ring_[head_]) > 0.0;
    if (!moving) scale_.snap();  // nothing to ramp: an override set before a start applies at once
    else if (clock_fraction_ > 0.0 && scale_.steady_at_one()) scale_.trim(clock_fraction_, period_);  // off the grid
    const double advanced = scale_.advance(period_);
    clock_fraction_ += advanced;
    const double whole = clock_fraction_ >= 1.0 ? static_cast<double>(static_cast<std::int64_t>(clock_fraction_)) : 0.0;
    clock_tick_ += static_cast<std::int64_t>(whole);
    clock_fraction_ -= whole;
    // Back onto the planned sample grid: at rest at once (nothing moves), after a trim its rounding.
    // At rest up to the next tick, unless a leg starting in this period would then show more of
    // its motion in its first sample than the clock moved (the paper's chain resumed at rest: 2
    // periods of a start in one sample, 1.08x the jerk limit in the samples' differences,
    // RateLimits seed 0 program 307); then down, if the leg has started by then, else off the
    // grid (the trim brings it back at rate 1).
    const bool rounding = scale_.steady_at_one() && (clock_fraction_ < 1e-9 || clock_fraction_ > 1.0 - 1e-9);
    if (clock_fraction_ > 0.0 && !moving) {
        const double into = count_ > 0 ? clock_time(ring_[head_]) : -HUGE_VAL;  // the next leg's time now
        if (into + (1.0 - clock_fraction_) * period_ <= advanced * period_) ++clock_tick_, clock_fraction_ = 0.0;
        else if (into - clock_fraction_ * period_ > 0.0) clock_fraction_ = 0.0;
    } else if (clock_fraction_ > 0.0 && rounding) {
        if (clock_fraction_ > 0.5) ++clock_tick_;
        clock_fraction_ = 0.0;
    }
}

}  // namespace firtp
