#include <firtp/hal/event_queue.hpp>

#include <cmath>

namespace firtp {

namespace {

bool waits(EventKind code) {
    return code == EventKind::tool_change || code == EventKind::pause || code == EventKind::optional_pause;
}

}  // namespace

bool EventQueue::push(const Event& event) {
    if (count_ == capacity) return false;
    if (event.code == EventKind::dwell) dwell_ += event.value;
    ring_[(head_ + count_) % capacity] = event;
    ++count_;
    if (waits(event.code)) ++gates_;
    return true;
}

double EventQueue::take_dwell() {
    const double d = dwell_;
    dwell_ = 0.0;
    return d;
}

bool EventQueue::fire(const Event& e, const EventInputs& in, EventOutputs& out) {
    ++fired_;
    out.events = fired_;
    out.line = e.line;
    switch (e.code) {
        case EventKind::spindle_clockwise:
        case EventKind::spindle_counterclockwise: {
            const bool forward = e.code == EventKind::spindle_clockwise;
            out.spindle_on = true;
            out.spindle_forward = forward;
            out.spindle_reverse = !forward;
            out.spindle_speed = forward ? std::abs(e.value) : -std::abs(e.value);
            return false;
        }
        case EventKind::spindle_stop:
            out.spindle_on = out.spindle_forward = out.spindle_reverse = false;
            return false;
        case EventKind::spindle_speed:  // S: the speed in force, signed as the spindle turns
            out.spindle_speed = out.spindle_reverse ? -std::abs(e.value) : std::abs(e.value);
            return false;
        case EventKind::tool_select: out.tool_prep_number = static_cast<std::int32_t>(e.value); return false;
        case EventKind::tool_change:
            out.tool_prep_number = static_cast<std::int32_t>(e.value);
            out.tool_change = true;
            return true;
        case EventKind::flood_on: out.coolant_flood = true; return false;
        case EventKind::mist_on: out.coolant_mist = true; return false;
        case EventKind::coolant_off: out.coolant_flood = out.coolant_mist = false; return false;
        case EventKind::pause:
        case EventKind::optional_pause:
            if (e.code == EventKind::optional_pause && !in.optional_stop) return false;
            out.paused = true;
            return true;
        case EventKind::dwell: return false;  // the rest is in the timeline
        case EventKind::program_end:
            out.program_end = true;
            out.spindle_on = out.spindle_forward = out.spindle_reverse = false;  // M2/M30 as LinuxCNC
            out.coolant_flood = out.coolant_mist = false;
            return false;
    }
    return false;
}

void EventQueue::update(std::uint64_t finished, bool at_rest, const EventInputs& in, EventOutputs& out) {
    const bool resume_rose = in.resume && !resume_was_;
    resume_was_ = in.resume;
    if (waiting_ && out.tool_change && in.tool_changed) {
        out.tool_change = false;
        out.tool_number = out.tool_prep_number;
        waiting_ = false;
        --gates_;
    }
    if (waiting_ && out.paused && resume_rose) {
        out.paused = false;
        waiting_ = false;
        --gates_;
    }
    while (!waiting_ && count_ > 0) {
        const Event& e = ring_[head_];
        if (e.after_blocks > finished || (waits(e.code) && !at_rest)) break;
        const bool opened = fire(e, in, out);
        head_ = (head_ + 1) % capacity;
        --count_;
        if (opened) waiting_ = true;
        else if (waits(e.code)) --gates_;  // an M1 without optional-stop: no wait
    }
}

void EventQueue::clear(EventOutputs& out) {
    head_ = count_ = 0;
    gates_ = 0;
    waiting_ = false;
    dwell_ = 0.0;
    out.tool_change = false;
    out.paused = false;
}

}  // namespace firtp
