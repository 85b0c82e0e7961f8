#include <firtp/interpolator.hpp>

#include <cmath>

namespace firtp {

Interpolator::Interpolator(const FirChain& chain, double period, std::size_t capacity, const AxisVector& start,
                           const RateLimits& rates)
    : chain_(&chain), period_(period), ring_(capacity), base_(start), scale_(rates) {}

void Interpolator::reset(const AxisVector& position) {
    head_ = 0;
    count_ = 0;
    base_ = position;
    line_ = 0;
    aborting_ = false;
    flushed_ = false;
}

void Interpolator::brake_from(const AxisVector& position, const AxisVector& velocity) {
    const double td = chain_->delay();
    reset(position - velocity * (0.5 * td));  // S(Td) = 1/2 of a pulse of width Td
    PlannedBlock b;
    b.tv = td;
    b.delta = velocity * td;
    b.end = position + velocity * (0.5 * td);
    const double start = static_cast<double>(clock_tick_) + clock_fraction_ - td / period_;  // periods
    b.start_tick = static_cast<std::int64_t>(std::floor(start));
    b.start_offset = (start - static_cast<double>(b.start_tick)) * period_;
    push(b);
    scale_.set_target(1.0);
    scale_.snap();
}

bool Interpolator::push(const PlannedBlock& block) {
    if (count_ == ring_.size()) return false;
    ring_[(head_ + count_) % ring_.size()] = block;
    ++count_;
    return true;
}

void Interpolator::tick(AxisState& out) {
    const double td = chain_->delay();
    // Retire blocks whose window has passed: their end point becomes the rest position, exactly.
    while (count_ > 0) {
        const PlannedBlock& front = ring_[head_];
        if (local_time(front) < front.tv + td) break;
        base_ = front.end;
        head_ = (head_ + 1) % ring_.size();
        --count_;
    }
    AxisVector velocity = AxisVector::Zero(), acceleration = AxisVector::Zero(), jerk = AxisVector::Zero();
    out.time = static_cast<double>(ticks_) * period_;
    out.position = base_;
    for (std::size_t i = 0; i < count_; ++i) {
        const PlannedBlock& b = ring_[(head_ + i) % ring_.size()];
        const double t = local_time(b);
        if (t <= 0.0) break;  // blocks start in queue order
        const StepSample s = chain_->pulse(t, b.tv);
        out.position += b.delta * s.position;
        velocity += b.delta * s.velocity;
        acceleration += b.delta * s.acceleration;
        jerk += b.delta * s.jerk;
        line_ = b.line;
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
    const bool moving = count_ > 0 && local_time(ring_[head_]) > 0.0;
    if (!moving) scale_.snap();  // nothing to ramp: an override set before a start applies at once
    else if (clock_fraction_ > 0.0 && scale_.steady_at_one()) scale_.trim(clock_fraction_, period_);  // off the grid
    clock_fraction_ += scale_.advance(period_);
    const double whole = clock_fraction_ >= 1.0 ? static_cast<double>(static_cast<std::int64_t>(clock_fraction_)) : 0.0;
    clock_tick_ += static_cast<std::int64_t>(whole);
    clock_fraction_ -= whole;
    // Back onto the planned sample grid: at rest at once (nothing moves), after a trim its rounding.
    const bool rounding = scale_.steady_at_one() && (clock_fraction_ < 1e-9 || clock_fraction_ > 1.0 - 1e-9);
    if (clock_fraction_ > 0.0 && (!moving || rounding)) {
        if (!moving || clock_fraction_ > 0.5) ++clock_tick_;
        clock_fraction_ = 0.0;
    }
}

}  // namespace firtp
