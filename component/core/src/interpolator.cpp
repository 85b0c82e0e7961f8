#include <firtp/interpolator.hpp>

namespace firtp {

Interpolator::Interpolator(const FirChain& chain, double period, std::size_t capacity, const AxisVector& start)
    : chain_(&chain), period_(period), ring_(capacity), base_(start) {}

void Interpolator::reset(const AxisVector& position) {
    head_ = 0;
    count_ = 0;
    base_ = position;
    line_ = 0;
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
    out.time = static_cast<double>(now_tick_) * period_;
    out.position = base_;
    out.velocity.setZero();
    out.acceleration.setZero();
    out.jerk.setZero();
    for (std::size_t i = 0; i < count_; ++i) {
        const PlannedBlock& b = ring_[(head_ + i) % ring_.size()];
        const double t = local_time(b);
        if (t <= 0.0) break;  // blocks start in queue order
        const StepSample s = chain_->pulse(t, b.tv);
        out.position += b.delta * s.position;
        out.velocity += b.delta * s.velocity;
        out.acceleration += b.delta * s.acceleration;
        out.jerk += b.delta * s.jerk;
        line_ = b.line;
    }
    if (count_ == 0) line_ = 0;
    out.line = line_;
    ++now_tick_;
}

}  // namespace firtp
