// The real-time side: evaluates the FIR chain's output for the queued blocks, one servo tick at a
// time. No allocation after construction, no locks, no I/O, no exceptions; per tick it costs
// O(stages) per moving block plus O(axes) per moving block, whatever the filter lengths.
//
// Drift: there are no running sums. A block whose filter window has passed is retired by setting
// the rest position to its programmed end point, so at rest the output equals the command
// exactly, after any number of ticks.
//
// Feed override and hold scale the filters' clock (TimeScale): the tool stays on the planned path
// and, at rate 1, the clock advances by whole periods so the samples are those of the plan.
#pragma once

#include <firtp/fir_chain.hpp>
#include <firtp/time_scale.hpp>
#include <firtp/types.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace firtp {

// A block as the planner scheduled it.
struct PlannedBlock {
    AxisVector delta = AxisVector::Zero();  // end - start
    AxisVector end = AxisVector::Zero();    // programmed end point, exact
    double tv = 0.0;                        // velocity pulse width Tv = L / F (Eq. 5)
    std::int64_t start_tick = 0;            // pulse starts at start_tick * period + start_offset
    double start_offset = 0.0;              // in [0, period)
    std::int64_t line = 0;
    MotionType type = MotionType::feed;
};

class Interpolator {
public:
    // `rates` bounds how fast override, hold and abort change the rate (rate_limits(parameters)).
    Interpolator(const FirChain& chain, double period, std::size_t capacity, const AxisVector& start,
                 const RateLimits& rates = {});

    // Non-real-time setup: rest at `position`, queue empty, clock kept.
    void reset(const AxisVector& position);

    // The axes are at `position` moving at `velocity` (found so at a start): drop the queue and
    // continue through `position` at that velocity, then stop through the chain as if a pulse of
    // width Td had run for Td already (braking.hpp); rest at braking_rest(). Rate 1 at once.
    void brake_from(const AxisVector& position, const AxisVector& velocity);

    bool push(const PlannedBlock& block);  // false when full; nothing changes then
    void tick(AxisState& out);             // state at the current clock, then one period on

    // Feed override (>= 0) or hold (rate 0), reached along an S-curve ramp.
    void set_rate(double rate) { scale_.set_target(rate); }
    // Stop along the path, then drop every queued block and rest where the tool stopped.
    void abort() { aborting_ = true; }
    bool aborting() const { return aborting_; }
    // True once after an abort finished; the planner must then be reset to rest_position().
    bool take_flushed() {
        const bool f = flushed_;
        flushed_ = false;
        return f;
    }

    // Earliest filter-clock tick a new block may start at.
    std::int64_t now_tick() const { return clock_tick_ + (clock_fraction_ > 0.0 ? 1 : 0); }
    std::int64_t ticks() const { return ticks_; }  // servo periods run
    double period() const { return period_; }
    const TimeScale& time_scale() const { return scale_; }
    bool idle() const { return count_ == 0; }
    std::size_t depth() const { return count_; }  // blocks not yet finished
    std::size_t free() const { return ring_.size() - count_; }
    const AxisVector& rest_position() const { return base_; }
    std::int64_t current_line() const { return line_; }

private:
    double local_time(const PlannedBlock& b) const {
        return (static_cast<double>(clock_tick_ - b.start_tick) + clock_fraction_) * period_ - b.start_offset;
    }

    const FirChain* chain_;
    double period_;
    std::vector<PlannedBlock> ring_;  // sized once
    std::size_t head_ = 0;
    std::size_t count_ = 0;
    AxisVector base_;  // end point of the last retired block
    std::int64_t ticks_ = 0;
    std::int64_t clock_tick_ = 0;    // filter clock = (clock_tick_ + clock_fraction_) periods
    double clock_fraction_ = 0.0;    // in [0, 1)
    TimeScale scale_;
    bool aborting_ = false;
    bool flushed_ = false;
    std::int64_t line_ = 0;
};

}  // namespace firtp
