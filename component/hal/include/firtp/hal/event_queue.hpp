// Program events in the HAL component: spindle, coolant, tool, pause, dwell and end, between
// blocks in program order (the host sends them in the blocks' (program, seq) sequence). Each waits
// in a fixed-size queue beside the planner's blocks and fires when motion reaches it: when the
// blocks accepted before it have finished. Real-time: no allocation.
//
// Where motion waits, as in LinuxCNC: a tool change until tool-changed is set, a pause (M0, and
// M1 while optional-stop is set) until resume rises. Both come after an exact stop and fire at
// rest; the component takes no record after them until they are done. A dwell is a rest of its
// length in the planner's timeline (Block::dwell of the next block), not a wait here.
#pragma once

#include <firtp/event_kind.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace firtp {


struct EventInputs {
    bool tool_changed = false;
    bool resume = false;
    bool optional_stop = false;
};

// What the events reached so far have set (LinuxCNC's motion.spindle-* and iocontrol.0.* pins).
struct EventOutputs {
    bool spindle_on = false, spindle_forward = false, spindle_reverse = false;
    double spindle_speed = 0.0;  // rpm, negative for M4
    bool coolant_flood = false, coolant_mist = false;
    std::int32_t tool_prep_number = 0, tool_number = 0;
    bool tool_change = false;
    bool paused = false;
    bool program_end = false;
    std::uint32_t events = 0;    // fired so far
    std::int64_t line = 0;       // line of the last one fired
};

struct Event {
    EventKind code = EventKind::program_end;
    double value = 0.0;          // rpm, tool number or seconds
    std::int64_t line = 0;
    std::uint64_t after_blocks = 0;  // fires once this many blocks have finished
};

class EventQueue {
public:
    static constexpr std::size_t capacity = 64;

    std::size_t free() const { return capacity - count_; }
    // Queues an event after `accepted` blocks; false when full. A dwell adds to dwell() instead.
    bool push(const Event& event);
    // No record may follow yet: a tool change or pause is queued or under way.
    bool gated() const { return gates_ > 0; }
    // The dwell for the next block (and cleared).
    double take_dwell();
    // Fires what motion has reached (`finished` blocks done, `at_rest`) and runs the handshakes.
    void update(std::uint64_t finished, bool at_rest, const EventInputs& in, EventOutputs& out);
    // A program was stopped: its queued events never fire; an open wait ends.
    void clear(EventOutputs& out);
    void new_program(EventOutputs& out) { out.program_end = false; }
    // How many fired since construction.
    std::uint32_t fired() const { return fired_; }

private:
    bool fire(const Event& e, const EventInputs& in, EventOutputs& out);  // true: a wait opens

    std::array<Event, capacity> ring_{};
    std::size_t head_ = 0, count_ = 0;
    int gates_ = 0;               // waiting events queued or open
    bool waiting_ = false;        // a tool change or pause is open
    bool resume_was_ = false;     // resume at the last update (a pause waits for a rising edge)
    double dwell_ = 0.0;
    std::uint32_t fired_ = 0;
};

}  // namespace firtp
