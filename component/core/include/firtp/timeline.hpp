// The real-time side: the planned legs, evaluated one servo tick at a time. No allocation after
// construction, no locks, no I/O, no exceptions; per tick O(axes) per leg in motion.
//
// A leg is one velocity pulse of the command (Eq. 5): the tool moves `delta` along a straight
// line; the pulse rises at one edge and falls at the other, each smoothed by its own kernel
// (kernel.hpp). Its progress, from 0 to 1, is
//     S(t) = (R_rise(t) - R_fall(t - fall)) / tv,   t from the start of the rising kernel,
// so the paper's pulse (both kernels the chain, fall = tv) is the special case. Consecutive legs
// share an edge: the falling edge of one and the rising edge of the next have the same kernel and
// time, and together they are the step from one velocity to the next.
//
// Drift: there are no running sums. A leg whose falling kernel has passed is retired by setting
// the rest position to its programmed end point, so at rest the output equals the command
// exactly, after any number of ticks.
//
// The planner appends legs before their kernels start and may change a leg's falling edge until
// its kernel starts (a hold, a new block, an override); what has started is never changed.
//
// The paper's mode keeps feed override and hold as a scaled clock (TimeScale): the filters' clock
// advances by rate * period each period, so the tool stays on the planned path; at rate 1 the
// clock advances by whole periods and the samples are those of the plan. The limit-driven mode
// leaves the rate at 1 and plans the override instead (lookahead.hpp).
#pragma once

#include <firtp/kernel.hpp>
#include <firtp/time_scale.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace firtp {

// Times on the tick grid are t = tick * period + offset: moves whole periods of `offset` into
// `tick`, so that offset lies in [0, period).
void normalise(std::int64_t& tick, double& offset, double period);

struct Leg {
    AxisVector delta = AxisVector::Zero();  // end - start
    AxisVector end = AxisVector::Zero();    // exact end point
    double tv = 0.0;                        // pulse width: |delta| / speed (Eq. 5)
    std::int64_t rise_tick = 0;             // the rising kernel starts at rise_tick * period + rise_offset
    double rise_offset = 0.0;               // in [0, period)
    double fall = 0.0;                      // the falling kernel starts this long after the rising one
    Kernel rising;
    Kernel falling;
    std::int64_t line = 0;
    MotionType type = MotionType::feed;
    bool last_of_block = false;             // it ends its block: the block is done when it retires

    // At rest this long after the rise: both kernels passed (a wide rising edge may outlast a
    // short leg's narrow falling one).
    double finish() const { return std::max(fall + falling.width(), rising.width()); }
    StepSample progress(double t) const;                        // S(t) and its derivatives
};

class Timeline {
public:
    // `max_width`: no kernel is wider (legs are visited in order until one cannot have started;
    // widen() raises it). `rates` bounds how fast a scaled clock changes its rate.
    Timeline(double period, std::size_t capacity, const AxisVector& start, double max_width,
             const RateLimits& rates = {});

    // Non-real-time setup: rest at `position`, no legs, clock kept.
    void reset(const AxisVector& position);

    bool push(const Leg& leg);  // false when full; nothing changes then
    void widen(double max_width) { max_width_ = std::max(max_width_, max_width); }
    void tick(AxisState& out);  // state at the current tick, then one period on

    // The scaled clock (paper's mode): feed override (>= 0) or hold (rate 0) along an S-curve
    // ramp; abort stops along the path, then drops every leg and rests where the tool stopped.
    void set_rate(double rate) { scale_.set_target(rate); }
    // The scaled clock at `rate` at once, on the tick grid (a stop from the feedback starts now).
    void snap_rate(double rate) {
        scale_.set_target(rate);
        scale_.snap();
        if (clock_fraction_ > 0.0) ++clock_tick_;
        clock_fraction_ = 0.0;
    }
    void abort() { aborting_ = true; }
    bool aborting() const { return aborting_; }
    bool take_flushed() {  // true once after an abort finished
        const bool f = flushed_;
        flushed_ = false;
        return f;
    }
    const TimeScale& time_scale() const { return scale_; }

    std::int64_t now() const { return clock_tick_ + (clock_fraction_ > 0.0 ? 1 : 0); }  // earliest tick a leg may start at
    std::int64_t ticks() const { return ticks_; }  // servo periods run
    double period() const { return period_; }
    double seconds(std::int64_t tick, double offset) const {  // from now
        return static_cast<double>(tick - now()) * period_ + offset;
    }
    bool idle() const { return count_ == 0; }
    std::size_t size() const { return count_; }
    std::size_t free() const { return ring_.size() - count_; }
    Leg& at(std::size_t i) { return ring_[(head_ + i) % ring_.size()]; }  // 0 = oldest
    const Leg& at(std::size_t i) const { return ring_[(head_ + i) % ring_.size()]; }
    Leg& back() { return at(count_ - 1); }
    const AxisVector& rest_position() const { return base_; }  // end of the last retired leg
    std::int64_t current_line() const { return line_; }
    std::uint64_t retired() const { return retired_; }          // legs retired since construction
    std::uint64_t blocks_retired() const { return blocks_retired_; }  // legs with last_of_block, likewise

    // Time since the rising kernel of `leg` started, at the clock `tick` (no fraction).
    double local_time(const Leg& leg, std::int64_t tick) const {
        return static_cast<double>(tick - leg.rise_tick) * period_ - leg.rise_offset;
    }

private:
    double clock_time(const Leg& leg) const {  // at the current (scaled) clock
        return (static_cast<double>(clock_tick_ - leg.rise_tick) + clock_fraction_) * period_ - leg.rise_offset;
    }
    // No kernel of this leg, nor of any later one, can have started: the leg's rising edge is more
    // than half the widest kernel away (edges are in command order).
    bool beyond(const Leg& leg, double t) const { return t < 0.5 * (leg.rising.width() - max_width_); }

    double period_;
    double max_width_;
    std::vector<Leg> ring_;  // sized once
    std::size_t head_ = 0;
    std::size_t count_ = 0;
    AxisVector base_;
    std::int64_t clock_tick_ = 0;   // filters' clock = (clock_tick_ + clock_fraction_) periods
    double clock_fraction_ = 0.0;   // in [0, 1)
    std::int64_t ticks_ = 0;        // periods run (the time of the output)
    std::int64_t line_ = 0;
    std::uint64_t retired_ = 0;
    std::uint64_t blocks_retired_ = 0;
    TimeScale scale_;
    bool aborting_ = false;
    bool flushed_ = false;
};

}  // namespace firtp
