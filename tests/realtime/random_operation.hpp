// Random programs and a random operator for the component's servo-thread logic (ComponentLogic),
// shared by the real-time proof (tests/realtime), the worst-tick benchmark (tests/bench) and the
// soak (tests/soak).
//
// Per servo period: before_tick() feeds the block stream (a fixed ring, as hal_stream) and moves
// the operator's controls; the caller runs ComponentLogic::update; after_tick() checks the output.
// Programs: random straight moves (0.01-40 mm, 40 % of them below 0.2 mm, 20-400 mm/s, tolerance 0.002-0.5 mm, some exact
// stops, traverses, zero-length and dense short blocks) in a box, sent with program id and seq.
// The operator: feed override (0 to the highest override), holds and resumes, aborts, disabling,
// and faults in the stream: a repeated block (must be refused and not run), a sequence gap and a
// NaN feed (the program must stop on the path with that error).
// Checked every period: finite output; velocity and acceleration within the axis limits (the
// chain's values at the sample). At the end of each completed program: the rest position equals
// the last block's target within 1e-9 mm, and every block was accepted exactly once
// (next_seq = blocks + 1; each repeat refused). Nothing here allocates after construction.
#pragma once

#include <firtp/hal/component_logic.hpp>
#include <firtp/machine.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>

namespace firtp::test {

// The block stream as the component reads it: a fixed ring, no allocation.
struct StreamRing {
    static constexpr std::size_t capacity = 256;
    std::array<stream::BlockRecord, capacity> records{};
    std::size_t head = 0, count = 0;

    bool full() const { return count == capacity; }
    bool push(const stream::BlockRecord& r) {
        if (full()) return false;
        records[(head + count) % capacity] = r;
        ++count;
        return true;
    }
    static bool read(void* self, stream::BlockRecord& r) {
        auto* s = static_cast<StreamRing*>(self);
        if (s->count == 0) return false;
        r = s->records[s->head];
        s->head = (s->head + 1) % capacity;
        --s->count;
        return true;
    }
    BlockSource source() { return {read, this}; }
};

// The built-in machine (300 mm/s, 5000 mm/s^2, 1e5 mm/s^3: smoothing at the limits) planned for a
// highest override of `max_rate`, or (limits = false) the paper's fixed chain T1 148 / T2 89 ms,
// no limits.
inline ComponentSettings operation_settings(bool limits, double max_rate = 1.5) {
    ComponentSettings s;
    if (limits) {
        MachineConfig m = default_machine();
        m.max_feed_override = max_rate;
        s.planner = m.planner_parameters();
    } else {
        s.planner.fixed_chain = true;
        s.planner.filters.stages = 2;
        s.planner.filters.T = {0.148, 0.089, 0.0, 0.0};
        s.planner.period = 0.001;
        s.planner.max_rate = max_rate;
    }
    s.axes = 3;
    return s;
}

struct OperationOptions {
    // Operator events, mean number per second of machine time.
    double overrides_per_s = 0.5;
    double holds_per_s = 0.1;
    double aborts_per_s = 0.02;
    double disables_per_s = 0.005;
    double coast_chance = 0.5;  // the axes still move when enable rises: the component brakes from vel-fb
    // Stream faults, per block sent.
    double repeat_chance = 0.005;
    double gap_chance = 0.0005;
    double nan_chance = 0.0005;
    int max_program_blocks = 400;
    int blocks_per_tick = 256;  // blocks written into the stream before a period, at most
};

struct OperationStats {
    std::int64_t ticks = 0;
    std::int64_t blocks = 0;          // sent once (repeats not counted)
    std::int64_t programs = 0;        // started
    std::int64_t completed = 0;       // ran to their end, end position checked
    std::int64_t aborted = 0;
    std::int64_t disabled = 0;
    std::int64_t braked = 0;          // enables while moving, braked from the feedback with that error
    std::int64_t faulted = 0;         // stopped by a gap or a NaN block, with that error
    std::int64_t repeats = 0;         // repeated blocks sent, each refused
    std::int64_t overrides = 0, holds = 0;
    double worst_end_error = 0.0;     // mm, completed programs
    double worst_limit_ratio = 0.0;   // |v| / v_max, |a| / a_max at the samples
    std::int64_t violations = 0;      // failed checks; the first is printed
    char first_violation[256] = "";
};

class RandomOperation {
public:
    RandomOperation(const ComponentSettings& settings, std::uint64_t seed, const OperationOptions& options = {})
        : settings_(settings), options_(options), rng_(seed) {
        limits_ = settings.planner.limits;
        has_limits_ = limits_.axis[0].max_velocity > 0.0;
        next_program(0);
    }

    const OperationStats& stats() const { return stats_; }
    bool ok() const { return stats_.violations == 0; }
    // What the next ComponentLogic::update gets.
    const ComponentInputs& inputs() const { return in_; }

    // Feeds the stream and moves the operator's controls for the next period.
    void before_tick(StreamRing& ring) {
        const double dt = settings_.planner.period;
        if (disabled_ticks_ > 0) {
            in_.enable = --disabled_ticks_ == 0;
            if (in_.enable && event(options_.coast_chance)) {  // the axes coast: up to 1.5 x their limits
                for (int a = 0; a < settings_.axes; ++a)
                    in_.velocity_feedback[a] = (2.0 * unit() - 1.0) * 1.5 * (has_limits_ ? limits_.axis[a].max_velocity : 200.0);
                expected_ = ComponentError::stopped_from_feedback;
                ++stats_.braked;
            }
            return;
        }
        for (int n = 0; phase_ == Phase::sending && n < options_.blocks_per_tick && !ring.full() && blocks_left_ > 0; ++n)
            send(ring);
        if (phase_ == Phase::stopping) return;
        if (hold_ticks_ > 0 && --hold_ticks_ == 0) in_.hold = false;
        if (event(options_.overrides_per_s * dt)) {
            const double u = unit(), top = settings_.planner.max_rate;
            in_.feed_scale = u < 0.05 ? 0.0 : u < 0.4 ? top : u < 0.7 ? 1.0 : 0.2 + (top - 0.2) * unit();
            ++stats_.overrides;
        }
        if (!in_.hold && event(options_.holds_per_s * dt)) {
            in_.hold = true;
            hold_ticks_ = 1 + static_cast<int>(unit() * 2.0 / dt);
            ++stats_.holds;
        }
        if (event(options_.aborts_per_s * dt)) {
            in_.abort = true;
            stop();
            ++stats_.aborted;
        } else if (event(options_.disables_per_s * dt)) {
            in_.enable = false;
            disabled_ticks_ = 1 + static_cast<int>(unit() * 0.2 / dt);
            stop();
            ++stats_.disabled;
        }
    }

    // Checks one period's output and moves the program along.
    void after_tick(const ComponentOutputs& out, const StreamRing& ring) {
        ++stats_.ticks;
        const AxisState& s = out.state;
        in_.position_feedback = s.position;  // an ideal drive: the axes are where commanded
        in_.velocity_feedback = s.velocity;
        for (int a = 0; a < settings_.axes; ++a) {
            if (!std::isfinite(s.position[a]) || !std::isfinite(s.velocity[a]) || !std::isfinite(s.acceleration[a]))
                return violation("tick %lld: non-finite output", static_cast<long long>(stats_.ticks));
            if (has_limits_) {
                const double rv = std::abs(s.velocity[a]) / limits_.axis[a].max_velocity;
                const double ra = std::abs(s.acceleration[a]) / limits_.axis[a].max_acceleration;
                stats_.worst_limit_ratio = std::max({stats_.worst_limit_ratio, rv, ra});
                if (rv > 1.0 + 1e-6 || ra > 1.0 + 1e-6)
                    return violation("tick %lld: axis %d beyond its limits: v %.9g a %.9g", static_cast<long long>(stats_.ticks), a,
                                     s.velocity[a], s.acceleration[a]);
            }
        }
        if (!in_.enable) return;
        const bool at_rest = out.done && out.mode != ComponentState::aborting;
        if (at_rest && !s.velocity.isZero(0.0)) return violation("program %u: at rest with a velocity", program_);
        switch (phase_) {
        case Phase::sending:
            break;
        case Phase::draining:
            if (expected_ != ComponentError::none) {  // a fault was sent: the program must stop with it
                if (out.error == expected_ && out.mode == ComponentState::error) {
                    phase_ = Phase::stopping;
                } else if (at_rest && ring.count == 0) {
                    return violation("program %u: ended with error %d state %d, expected error %d", program_,
                                     static_cast<int>(out.error), static_cast<int>(out.mode), static_cast<int>(expected_));
                }
                break;
            }
            if (!at_rest || in_.hold || in_.feed_scale == 0.0 || ring.count != 0) break;
            if (out.next_seq != seq_ + 1)  // every block accepted once: nothing skipped
                return violation("program %u: at rest with next_seq %llu after %u blocks", program_,
                                 static_cast<unsigned long long>(out.next_seq), seq_);
            if (out.rejected - rejected_base_ != repeats_)  // every repeat refused, nothing else
                return violation("program %u: %u blocks refused, %u repeats sent", program_, out.rejected - rejected_base_, repeats_);
            {
                const double error = (s.position - target_).head(settings_.axes).cwiseAbs().maxCoeff();
                stats_.worst_end_error = std::max(stats_.worst_end_error, error);
                if (error > 1e-9) return violation("program %u ended %.3g mm from its last target", program_, error);
            }
            ++stats_.completed;
            next_program(out.rejected);
            break;
        case Phase::stopping:
            if (!at_rest) break;
            if (expected_ != ComponentError::none) {
                if (out.error != expected_)
                    return violation("program %u: error %d instead of %d", program_, static_cast<int>(out.error),
                                     static_cast<int>(expected_));
                ++stats_.faulted;
            }
            in_.abort = false;
            in_.hold = false;
            hold_ticks_ = 0;
            // Blocks of this program still in the stream are refused when read: not this program's.
            next_program(out.rejected + static_cast<std::uint32_t>(ring.count));
            break;
        }
    }

private:
    enum class Phase { sending, draining, stopping };

    double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
    bool event(double chance) { return unit() < chance; }

    template <typename... A>
    void violation(const char* format, A... args) {
        if (stats_.violations++ == 0)
            std::snprintf(stats_.first_violation, sizeof stats_.first_violation, format, args...);
    }

    void stop() {
        phase_ = Phase::stopping;
        expected_ = ComponentError::none;
        blocks_left_ = 0;
    }

    void next_program(std::uint32_t rejected) {
        ++program_;
        ++stats_.programs;
        phase_ = Phase::sending;
        seq_ = 0;
        repeats_ = 0;
        expected_ = ComponentError::none;
        blocks_left_ = 1 + static_cast<int>(unit() * options_.max_program_blocks);
        rejected_base_ = rejected;
    }

    void send(StreamRing& ring) {
        if (seq_ > 0 && unit() < options_.repeat_chance) {  // a block sent again: refused, never run twice
            ring.push(last_);
            ++repeats_;
            ++stats_.repeats;
            return;
        }
        stream::BlockRecord r;
        r.program = program_;
        Block& b = r.block;
        const double shape = unit();
        const double length = shape < 0.01  ? 0.0                    // zero length: accepted and skipped
                              : shape < 0.4 ? 0.01 + 0.2 * unit()  // dense (CAM chords)
                              : shape < 0.9 ? 0.2 + 10.0 * unit()
                                            : 10.0 + 30.0 * unit();
        // Mostly a gentle turn from the last direction (curves, CAM chords), sometimes any corner.
        AxisVector turn = AxisVector::Zero();
        for (int a = 0; a < settings_.axes; ++a) turn[a] = unit() - 0.5;
        AxisVector direction = unit() < 0.7 ? AxisVector(direction_ + 0.3 * turn) : turn;
        if (direction.norm() < 1e-3) direction[0] = 1.0;
        direction.normalize();
        b.target = target_ + direction * length;
        for (int a = 0; a < settings_.axes; ++a)  // keep inside a 400 mm box
            if (std::abs(b.target[a]) > 200.0) b.target[a] = target_[a] - direction[a] * length;
        b.feed = 20.0 + 380.0 * unit();
        b.tolerance = 0.002 + 0.5 * unit() * unit();
        b.termination = unit() < 0.05 ? Termination::exact_stop : Termination::blend;
        b.type = unit() < 0.03 ? MotionType::traverse : MotionType::feed;
        b.line = seq_ + 1;
        r.seq = ++seq_;
        if (unit() < options_.gap_chance) {
            r.seq = ++seq_;  // one seq skipped: the program must stop with a gap, this block unplanned
            expected_ = ComponentError::sequence_gap;
            blocks_left_ = 1;
        } else if (unit() < options_.nan_chance) {
            b.feed = std::numeric_limits<double>::quiet_NaN();
            expected_ = ComponentError::bad_value;
            blocks_left_ = 1;
        } else {
            target_ = b.target;
        }
        direction_ = direction;
        ring.push(r);
        last_ = r;
        ++stats_.blocks;
        if (--blocks_left_ == 0) phase_ = Phase::draining;
    }

    ComponentSettings settings_;
    OperationOptions options_;
    std::mt19937_64 rng_;
    MachineLimits limits_;
    bool has_limits_ = false;
    OperationStats stats_;
    ComponentInputs in_;
    Phase phase_ = Phase::sending;
    std::uint32_t program_ = 0;
    std::uint32_t seq_ = 0;
    int blocks_left_ = 0;
    std::uint32_t repeats_ = 0;
    std::uint32_t rejected_base_ = 0;
    ComponentError expected_ = ComponentError::none;
    AxisVector target_ = AxisVector::Zero();
    AxisVector direction_ = AxisVector::Unit(0);
    stream::BlockRecord last_;
    int hold_ticks_ = 0;
    int disabled_ticks_ = 0;
};

}  // namespace firtp::test
