// The LCM bridge: a non-real-time HAL component ("firtp-bridge") between LCM and the firtp
// component. Blocks from FIRTP_BLOCK are checked (the crc of the bytes as received first: a
// corrupted one is refused like a lost one), validated and sequenced (each (program, seq) once, in
// order) and written into the component's block stream; FIRTP_CONTROL drives the feed-scale,
// hold and abort pins; the component's status pins and axis-state stream go out, sealed, as
// FIRTP_STATUS and FIRTP_AXIS_STATE (every period) / FIRTP_AXIS_STATE_LIVE (decimated).
// The handoff to the servo thread is the lock-free hal_stream; nothing here blocks it.
#pragma once

#include <firtp/defaults.hpp>
#include <firtp/messages.hpp>
#include <firtp/types.hpp>

#include <cstdint>
#include <deque>
#include <optional>
#include <string>

namespace firtp {

namespace stream {
struct BlockRecord;
struct Progress;
}

struct BridgeOptions {
    const char* name = "firtp-bridge";  // HAL component name and pin prefix (pin_pairs() name the default)
    int block_key = firtp_lcm::config_t::BLOCK_STREAM_KEY;  // the component's block_key
    int state_key = firtp_lcm::config_t::STATE_STREAM_KEY;  // the component's state_key (0: no axis states)
    int axes = 3;
    double period = defaults::servo_period;  // servo period, s
    bool every_period = true;         // publish FIRTP_AXIS_STATE for every period
    int live_decimation = messages::default_live_decimation;  // FIRTP_AXIS_STATE_LIVE every N periods (0: never)
    int status_every = messages::default_status_every;        // FIRTP_STATUS every N periods, and on every change
    double max_feed_scale = 2.0;
};

class Bridge {
public:
    // Registers HAL component options.name with its pins and attaches to the streams; the caller
    // nets the pins (see pin_pairs()). Throws std::runtime_error on failure.
    Bridge(lcm::LCM& lcm, const BridgeOptions& options);
    ~Bridge();
    Bridge(const Bridge&) = delete;
    Bridge& operator=(const Bridge&) = delete;

    // Non-blocking: forwards axis states and publishes status. Blocks and control are handled
    // as LCM delivers them (in the thread that calls lcm.handle*).
    void poll();

    // "bridge-pin component-pin" pairs to net, in HAL naming.
    static const char* const* pin_pairs();

    std::int64_t blocks_forwarded() const { return forwarded_; }  // and events
    // Blocks and controls refused because their crc did not match (status_t corrupted).
    std::int64_t messages_corrupted() const { return corrupted_; }
    // Nothing queued in the component or its stream, and not aborting.
    bool idle() const { return component_idle(); }
    std::int64_t states_published() const { return states_; }

private:
    struct Pins;
    void on_block_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel);
    void on_control_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel);
    void on_event_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel);
    void on_block(const firtp_lcm::block_t* message);      // intact
    void on_event(const firtp_lcm::event_t* message);      // intact
    // Blocks and events in the sequence: an intact one goes to `intact`; a corrupted one is refused
    // like a lost one (the host resends it) and reported, named as far as its bytes allow.
    template <class Message>
    void on_sequenced_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel,
                            void (Bridge::*intact)(const Message*));
    // The sequence and the stream's room for a record (program, seq) named `name`; false (and
    // reported) when it must not go to the component.
    bool admit(std::int64_t program, std::int64_t seq, const std::string& name);
    void write(const stream::BlockRecord& record, std::int64_t program, std::int64_t seq);
    void publish_reached();
    void on_control(const firtp_lcm::control_t* message);  // intact
    void name_applied_control(std::uint32_t gen);
    void report(std::int32_t error, std::string text);
    void forward_states();
    void publish_status();
    bool component_idle() const;
    // Blocks not finished: the component's queue-depth pin plus the stream's depth. Read one after
    // the other, the two can tear (the component takes the last blocks from the stream, its pin
    // still says 0): at rest, the records written that the latest axis state does not count as
    // taken (its next_seq) are not finished either.
    std::int64_t component_depth() const;

    lcm::LCM* lcm_;
    BridgeOptions options_;
    int comp_id_ = -1;
    Pins* pins_ = nullptr;
    struct Streams;
    Streams* streams_ = nullptr;
    messages::SequenceChecker sequence_;
    bool fault_ = false;               // a bad block: abort until a new program starts; its error
                                       // stays in the status (later refusals are its echoes)
    std::int64_t control_session_ = 0;
    std::int64_t control_seq_ = 0;
    double feed_scale_ = 1.0;
    bool hold_ = false, abort_ = false;
    // Controls taken, in order, until an axis state names their generation or a later one.
    struct ControlTaken {
        std::uint32_t gen = 0;  // control_pins.hpp
        std::int64_t session = 0, seq = 0;
    };
    static constexpr std::size_t max_controls_unapplied = 1 << 16;
    std::uint32_t control_gen_ = 0;
    std::deque<ControlTaken> controls_taken_;
    ControlTaken applied_control_;  // named by the latest axis state
    bool unknown_gen_reported_ = false;
    // Taking over, a control that came before the first period was read: the generation in effect
    // is only known from a period (before lcm.hal's nets the pin reads its own 0; netting drives
    // that onto the signal, while the periods waiting name the old bridge's). It is taken after
    // that period. (A fresh start takes it at once, as logs recorded so replay.)
    std::optional<firtp_lcm::control_t> waiting_control_;
    // A bridge started again under a running component (firtp-lcm-bridge restarted while firtp.so
    // runs on) takes over what the one before left: the control generation in effect (it counts on
    // from it and names those levels control 0, without an error), and the component's program and
    // next seq, once the block stream is empty (every block written before taken) and a period that
    // began after that has reported them. Until then it publishes no FIRTP_STATUS (its pins may not
    // be netted yet) and refuses blocks of that program (any, before it has seen a period) for a
    // resend. A fresh component (its state stream empty when the bridge starts): nothing to take over.
    void inherit_control_gen(std::uint32_t gen);
    void take_over_sequence(std::int64_t tick, const stream::Progress& progress);
    bool gen_inherited_ = false;
    std::uint32_t inherited_gen_ = 0;
    bool taking_over_ = false;  // the component ran before: periods waiting, or a program not this bridge's
    bool period_seen_ = false;  // a period's progress drained
    bool sequence_taken_over_ = false;
    std::int64_t stream_empty_at_tick_ = -1;  // the tick pin when the block stream was seen empty
    std::int64_t reported_program_ = 0, reported_next_seq_ = 1;  // by the latest axis state
    std::int32_t error_ = 0;
    std::string error_text_;
    std::int64_t rejected_ = 0;
    std::int64_t corrupted_ = 0;
    std::int64_t forwarded_ = 0;
    std::int64_t states_ = 0;
    std::int64_t status_seq_ = 0;
    std::int64_t state_seq_ = 0;
    std::int64_t last_tick_ = -1;      // 64-bit extension of the stream's 32-bit tick
    std::int64_t lost_states_ = 0;     // periods missing from the ticks since the start
    std::int64_t periods_since_status_ = 0;
    bool status_due_ = true;
    lcm::Subscription* block_subscription_ = nullptr;
    lcm::Subscription* control_subscription_ = nullptr;
    lcm::Subscription* event_subscription_ = nullptr;
    std::deque<firtp_lcm::event_t> in_flight_;  // events forwarded, not reached yet, in order
    std::int64_t reached_ = -1;                 // the component's events count last seen (-1: none yet)
};

}  // namespace firtp
