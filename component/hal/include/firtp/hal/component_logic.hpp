// What the firtp HAL component does every servo period, free of HAL so it can be tested alone.
//
// Principle of operation: blocks arrive through the block pins (a strobe/ack handshake, one per
// period) or the block stream (many per period, from the LCM bridge). Each accepted block is
// checked (values, type, program and sequence number) and handed to the planner (planner.hpp),
// which plans its motion within the machine's limits and its corners within their tolerance.
// Every period the planner's timeline drives the axis outputs. Feed scale and hold are the
// planner's rate (0: stop on the path); abort stops on the path and drops the queue;
// disable drops everything at once (drives are off) and the outputs follow the position feedback,
// so that enabling moves nothing. At the first period and when enable rises the component takes
// over from the feedback: at rest there, or, if the axes move faster than brake_speed (a restart
// while moving), it continues at their velocity and stops through the chain within the limits
// (braking.hpp), reported as stopped_from_feedback. A bad block stops the program on the path and
// is reported: nothing after it runs, nothing runs twice.
#pragma once

#include <firtp/braking.hpp>
#include <firtp/defaults.hpp>
#include <firtp/parameters.hpp>
#include <firtp/planner.hpp>
#include <firtp/types.hpp>

#include <firtp/hal/event_queue.hpp>
#include <firtp/hal/stream_records.hpp>

#include <cstdint>

namespace firtp {

// Values as in firtp_lcm::status_t (static_assert in component/bridge/src/protocol_codes.cpp).
enum class ComponentState : std::int32_t { idle = 0, moving = 1, holding = 2, aborting = 3, error = 4, disabled = 5 };
enum class ComponentError : std::int32_t {
    none = 0, bad_value = 1, sequence_gap = 2, repeated = 3, queue_full = 4, bad_type = 5, not_enabled = 6, lost_state = 7,
    stopped_from_feedback = 8
};

struct ComponentSettings {
    PlannerParameters planner;           // planner.queue_capacity: blocks it holds at once
    int axes = 3;
    int max_blocks_per_period = defaults::max_blocks;  // stream records planned per period at most
    std::int64_t plan_budget_ns = defaults::plan_budget_us * 1000;  // and only while planning took less than this (0: no limit)
    std::int64_t (*clock_ns)() = nullptr;  // monotonic clock for the budget (the RTAPI clock in HAL)
    double default_tolerance = defaults::tolerance;  // for pin blocks whose tolerance is 0
    double brake_speed = defaults::brake_speed;  // feedback speed (units/s, any axis) that counts as moving at a start
};

struct ComponentInputs {
    bool enable = true;
    double feed_scale = 1.0;
    bool hold = false;
    bool abort = false;
    bool strobe = false;                 // pin block handshake
    stream::BlockRecord pin_block;
    std::int32_t pin_motion_type = 2;
    AxisVector position_feedback = AxisVector::Zero();  // where the axes are (pos-fb)
    AxisVector velocity_feedback = AxisVector::Zero();  // how fast they move (vel-fb)
    EventInputs events;                  // tool-changed, resume, optional-stop
};

struct ComponentOutputs {
    AxisState state;
    bool ack = false;
    bool busy = false;
    bool done = true;
    std::int32_t queue_depth = 0;
    std::int32_t queue_free = 0;
    ComponentState mode = ComponentState::idle;
    ComponentError error = ComponentError::none;
    std::uint64_t program = 0;           // the pins show the low 32 bits
    std::uint64_t next_seq = 1;
    std::uint32_t rejected = 0;
    EventOutputs events;                 // what the program events reached so far set
};

// Where stream records come from: returns false when none is waiting.
struct BlockSource {
    bool (*read)(void* context, stream::BlockRecord& record) = nullptr;
    void* context = nullptr;
};

class ComponentLogic {
public:
    explicit ComponentLogic(const ComponentSettings& settings);  // throws std::invalid_argument (init only)
    ComponentLogic(const ComponentLogic&) = delete;
    ComponentLogic& operator=(const ComponentLogic&) = delete;

    // One servo period; real-time: no allocation, locks, I/O or exceptions.
    void update(const ComponentInputs& in, BlockSource source, ComponentOutputs& out);

    const ComponentSettings& settings() const { return settings_; }

private:
    // Checks and plans one block; false (and the error latched) when it must not run.
    bool accept(const stream::BlockRecord& record, bool from_stream);
    bool accept_event(const stream::BlockRecord& record);  // queued after the blocks accepted so far
    bool may_read() const { return planner_.free() > 0 && events_.free() > 0 && !events_.gated(); }
    int refuse_inputs(const ComponentInputs& in, BlockSource source);  // counts what it refused
    void fail(ComponentError error);
    void drop_everything(const AxisVector& at);
    void take_over(const ComponentInputs& in);  // first period, or enable rose
    // The used axes' finite feedback pins, `otherwise` where a pin is not finite (or the axis unused).
    AxisVector feedback(const AxisVector& pins, const AxisVector& otherwise) const;

    ComponentSettings settings_;
    Planner planner_;
    EventQueue events_;                   // beside the planner's blocks (event_queue.hpp)
    EventOutputs event_state_;
    BrakingPeaks braking_;                // the paper's mode: how much of a velocity its chain can stop
    PlannerOutput last_{};               // the planner's output at the last period
    bool started_ = false;
    bool enabled_ = false;
    bool aborting_ = false;
    bool braking_now_ = false;            // stopping from the feedback velocity
    bool abort_pin_ = false;
    bool halted_ = false;                 // after a bad block: refuse the rest of that program
    bool unchecked_halted_ = false;       // and blocks with seq 0, until enable rises or abort falls
    bool ack_ = false;
    ComponentError error_ = ComponentError::none;
    std::uint64_t program_ = 0;
    std::uint64_t next_seq_ = 1;
    std::uint32_t rejected_ = 0;
};

}  // namespace firtp
