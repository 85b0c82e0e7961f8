#include <firtp/hal/component_logic.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace firtp {

namespace {

ComponentSettings checked(const ComponentSettings& s) {
    if (s.axes < 1 || s.axes > max_axes) throw std::invalid_argument("axes must be 1 to 9");
    if (s.planner.queue_capacity < 2) throw std::invalid_argument("queue must hold at least 2 blocks");
    if (s.max_blocks_per_period < 1) throw std::invalid_argument("max_blocks_per_period must be at least 1");
    if (!(s.default_tolerance > 0.0)) throw std::invalid_argument("the default tolerance must be positive");
    if (!(s.brake_speed >= 0.0 && std::isfinite(s.brake_speed)))
        throw std::invalid_argument("the brake speed must be a finite speed >= 0");
    return s;
}

}  // namespace

// Next stream record, if a stream is attached and holds one.
bool next_record(BlockSource& source, stream::BlockRecord& record) {
    return source.read != nullptr && source.read(source.context, record);
}

ComponentLogic::ComponentLogic(const ComponentSettings& settings)
    : settings_(checked(settings)), planner_(settings.planner, AxisVector::Zero()),
      braking_(settings.planner.fixed_chain ? braking_peaks(planner_.chain()) : BrakingPeaks{}) {}

void ComponentLogic::fail(ComponentError error) {
    error_ = error;
    halted_ = unchecked_halted_ = true;
    ++rejected_;
    events_.clear(event_state_);
    if (!planner_.idle()) {
        planner_.abort();  // stop on the path; the rest of the program must not run
        aborting_ = true;
    }
}

void ComponentLogic::drop_everything(const AxisVector& at) {
    planner_.reset(at);
    events_.clear(event_state_);
    aborting_ = false;
    halted_ = unchecked_halted_ = true;  // the interrupted program must not continue from here
}

AxisVector ComponentLogic::feedback(const AxisVector& pins, const AxisVector& otherwise) const {
    AxisVector value = otherwise;
    for (int a = 0; a < settings_.axes; ++a)
        if (std::isfinite(pins[a])) value[a] = pins[a];
    return value;
}

void ComponentLogic::take_over(const ComponentInputs& in) {
    const AxisVector at = feedback(in.position_feedback, last_.state.position);
    const AxisVector velocity = feedback(in.velocity_feedback, AxisVector::Zero());
    planner_.reset(at);
    unchecked_halted_ = false;  // enable rose: the operator's reset for blocks with seq 0
    if (velocity.cwiseAbs().maxCoeff() > settings_.brake_speed) {
        // Limit-driven: the stop's kernel is sized to the velocity, so only max_velocity bounds
        // it (braking_ is zero); the paper's chain can stop only a share of it.
        planner_.brake_from(at, velocity * braking_share(braking_, settings_.planner.limits, velocity));
        braking_now_ = true;
        error_ = ComponentError::stopped_from_feedback;
        halted_ = unchecked_halted_ = true;  // whatever moved the axes must not go on here
    }
}

bool ComponentLogic::accept(const stream::BlockRecord& record, bool from_stream) {
    const bool new_program = record.seq != 0 && record.program != program_;
    if (new_program) {
        if (!planner_.idle() || aborting_) {
            fail(ComponentError::sequence_gap);  // a new program while one is still running
            return false;
        }
        program_ = record.program;
        next_seq_ = 1;
        halted_ = false;
        error_ = ComponentError::none;
        events_.new_program(event_state_);
    }
    if (record.seq == 0 ? unchecked_halted_ : halted_) {  // the rest of a program that was stopped
        ++rejected_;
        return false;
    }
    if (record.seq != 0 && record.seq < next_seq_) {  // already ran: never twice
        error_ = ComponentError::repeated;
        ++rejected_;
        return false;
    }
    if (record.seq != 0 && record.seq > next_seq_) {
        fail(ComponentError::sequence_gap);
        return false;
    }
    if (!record.type_known) {
        fail(ComponentError::bad_type);
        return false;
    }
    if (record.is_event) return accept_event(record);
    Block block = record.block;
    block.dwell += events_.take_dwell();
    if (!from_stream && block.termination == Termination::blend && block.tolerance == 0.0)
        block.tolerance = settings_.default_tolerance;
    // The caller made room: only bad values are refused.
    if (const Result r = planner_.add(block); r != Result::ok && r != Result::skipped) {
        fail(ComponentError::bad_value);
        return false;
    }
    if (record.seq != 0) ++next_seq_;
    return true;
}

bool ComponentLogic::accept_event(const stream::BlockRecord& record) {
    const Event event{static_cast<EventKind>(record.event_code), record.event_value, record.block.line,
                      planner_.accepted()};
    if (!std::isfinite(event.value) || (event.code == EventKind::dwell && !(event.value >= 0.0 && event.value <= max_dwell))) {
        fail(ComponentError::bad_value);
        return false;
    }
    if (!events_.push(event)) {  // the caller made room
        fail(ComponentError::queue_full);
        return false;
    }
    if (event.code == EventKind::program_end) planner_.finish();  // no block follows: the last one ends the motion
    if (record.seq != 0) ++next_seq_;
    return true;
}

int ComponentLogic::refuse_inputs(const ComponentInputs& in, BlockSource source) {
    stream::BlockRecord record;
    int refused = 0;
    while (refused < settings_.max_blocks_per_period && next_record(source, record)) ++refused;
    if (in.strobe && !ack_) ++refused;  // a new pin block, acknowledged but not run
    ack_ = in.strobe;
    rejected_ += refused;
    return refused;
}

void ComponentLogic::update(const ComponentInputs& in, BlockSource source, ComponentOutputs& out) {
    if (!in.enable) {
        const AxisVector at = feedback(in.position_feedback, last_.state.position);
        if (enabled_ || !started_) drop_everything(at);  // drives are off: no deceleration, no queue
        enabled_ = false;
        braking_now_ = false;
        if (refuse_inputs(in, source) > 0) error_ = ComponentError::not_enabled;
        last_.state.position = at;  // follow the axes, so that enabling moves nothing
        // The planner's clock runs on (idle, its output unused): its times are then the same
        // whenever the machine is switched on, and so the trajectory, to the last bit (a replay
        // cannot know that period; docs/RECORDING.md).
        AxisState unused;
        planner_.tick(unused);
        last_.state.velocity.setZero();
        last_.state.acceleration.setZero();
        last_.state.jerk.setZero();
    } else {
        if (!enabled_) take_over(in);
        enabled_ = true;
        if (in.abort && !aborting_ && !braking_now_ && !planner_.idle()) {
            planner_.abort();
            aborting_ = true;
        }
        const bool stopping = in.hold || in.abort || aborting_;
        PlannerInput motion;
        motion.rate = braking_now_ ? 1.0 : std::clamp(in.feed_scale, 0.0, settings_.planner.max_rate);
        motion.hold = stopping && !braking_now_;
        planner_.set_rate(motion.hold ? 0.0 : motion.rate);  // now: the blocks below are planned at it

        if (in.abort || aborting_ || braking_now_) {  // refuse the rest of a stopped program
            refuse_inputs(in, source);
            if (in.abort) halted_ = unchecked_halted_ = true, events_.clear(event_state_);
        } else {
            if (!in.strobe) {
                ack_ = false;
            } else if (!ack_ && may_read()) {  // a full queue or a wait makes the feeder wait
                stream::BlockRecord pin = in.pin_block;
                pin.type_known = in.pin_motion_type == 1 || in.pin_motion_type == 2;
                pin.block.type = in.pin_motion_type == 1 ? MotionType::traverse : MotionType::feed;
                accept(pin, false);
                ack_ = true;
            }
            // At least one block a period; more while the planning budget lasts.
            const bool budgeted = settings_.plan_budget_ns > 0 && settings_.clock_ns != nullptr;
            const std::int64_t begin = budgeted ? settings_.clock_ns() : 0;
            stream::BlockRecord record;
            for (int k = 0; k < settings_.max_blocks_per_period && may_read() &&
                            (k == 0 || !budgeted || settings_.clock_ns() - begin < settings_.plan_budget_ns) &&
                            next_record(source, record);
                 ++k)
                accept(record, true);
        }
        planner_.update(motion, last_);
        if (last_.flushed) aborting_ = false, events_.clear(event_state_);  // at rest: the planner starts there
        else events_.update(planner_.finished(), planner_.idle(), in.events, event_state_);
        if (braking_now_ && planner_.idle()) braking_now_ = false;
    }
    if (abort_pin_ && !in.abort) unchecked_halted_ = false;  // abort fell: the operator's reset
    abort_pin_ = in.abort;
    started_ = true;

    out.state = last_.state;
    out.ack = ack_;
    out.busy = !planner_.idle();
    out.done = planner_.idle();
    out.queue_depth = static_cast<std::int32_t>(planner_.depth());
    out.queue_free = static_cast<std::int32_t>(planner_.free());
    out.mode = !enabled_                   ? ComponentState::disabled
               : aborting_ || braking_now_ ? ComponentState::aborting
               : !planner_.idle()          ? (in.hold ? ComponentState::holding : ComponentState::moving)
               : halted_ && error_ != ComponentError::none && error_ != ComponentError::repeated
                                           ? ComponentState::error
                                           : ComponentState::idle;
    out.error = error_;
    out.program = program_;
    out.next_seq = next_seq_;
    out.rejected = rejected_;
    out.events = event_state_;
}

}  // namespace firtp
