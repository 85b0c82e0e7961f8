#include <firtp/bridge.hpp>

#include <hal.h>

#include <firtp/hal/control_pins.hpp>
#include <firtp/hal/hal_pin_access.hpp>
#include <firtp/hal/stream_records.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace firtp {

namespace {

const char* describe_component_error(std::int32_t code) {
    switch (code) {
        case firtp_lcm::status_t::ERROR_BAD_VALUE: return "the component refused a block: bad value";
        case firtp_lcm::status_t::ERROR_SEQUENCE_GAP: return "the component saw a sequence gap";
        case firtp_lcm::status_t::ERROR_REPEATED: return "the component ignored a repeated block";
        case firtp_lcm::status_t::ERROR_BAD_TYPE: return "the component refused a block: unknown motion type";
        case firtp_lcm::status_t::ERROR_NOT_ENABLED: return "the component is not enabled: blocks dropped";
        case firtp_lcm::status_t::ERROR_STOPPED_FROM_FEEDBACK:
            return "the component started or was enabled while the machine moved: it stopped the axes from their feedback";
        default: return "the component reported an error";
    }
}

const char* const pairs[] = {
    "firtp-bridge.feed-scale", "firtp.feed-scale",       "firtp-bridge.hold",        "firtp.hold",
    "firtp-bridge.abort",      "firtp.abort",            "firtp-bridge.queue-depth", "firtp.queue-depth",
    "firtp-bridge.state",      "firtp.state",            "firtp-bridge.error-code",  "firtp.error-code",
    "firtp-bridge.rejected",   "firtp.rejected",         "firtp-bridge.tick",        "firtp.tick",
    "firtp-bridge.current-line", "firtp.current-line",   "firtp-bridge.events",      "firtp.events",
    "firtp-bridge.control-gen", "firtp.control-gen",     nullptr,                    nullptr};


}  // namespace

struct Bridge::Pins {
    hal_float_t* feed_scale;  // out: feed override for the component
    hal_bit_t* hold;          // out
    hal_bit_t* abort;         // out: operator abort, or a bad block
    hal_s32_t* queue_depth;   // in: the component's
    hal_s32_t* state;         // in
    hal_s32_t* error_code;    // in
    hal_u32_t* rejected;      // in
    hal_u32_t* tick;          // in
    hal_s32_t* current_line;  // in
    hal_u32_t* events;        // in: program events the component has reached
    hal_u32_t* control_gen;   // out: the generation of feed_scale, hold and abort (control_pins.hpp)
};

struct Bridge::Streams {
    hal_stream_t blocks;
    hal_stream_t states;
    bool has_states = false;
    AxisState pending;  // axis state being assembled from its groups
    std::uint32_t pending_tick = 0;
    int pending_groups = 0;  // of pending_tick's, received in order
};

const char* const* Bridge::pin_pairs() { return pairs; }

Bridge::Bridge(lcm::LCM& lcm, const BridgeOptions& options) : lcm_(&lcm), options_(options) {
    const char* name = options.name;
    comp_id_ = hal_init(name);
    if (comp_id_ < 0) throw std::runtime_error(std::string(name) + ": hal_init failed");
    pins_ = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
    streams_ = new Streams;
    int r = pins_ ? 0 : -1;
    r = r ? r : hal_pin_float_newf(HAL_OUT, &pins_->feed_scale, comp_id_, "%s.feed-scale", name);
    r = r ? r : hal_pin_bit_newf(HAL_OUT, &pins_->hold, comp_id_, "%s.hold", name);
    r = r ? r : hal_pin_bit_newf(HAL_OUT, &pins_->abort, comp_id_, "%s.abort", name);
    r = r ? r : hal_pin_s32_newf(HAL_IN, &pins_->queue_depth, comp_id_, "%s.queue-depth", name);
    r = r ? r : hal_pin_s32_newf(HAL_IN, &pins_->state, comp_id_, "%s.state", name);
    r = r ? r : hal_pin_s32_newf(HAL_IN, &pins_->error_code, comp_id_, "%s.error-code", name);
    r = r ? r : hal_pin_u32_newf(HAL_IN, &pins_->rejected, comp_id_, "%s.rejected", name);
    r = r ? r : hal_pin_u32_newf(HAL_IN, &pins_->tick, comp_id_, "%s.tick", name);
    r = r ? r : hal_pin_s32_newf(HAL_IN, &pins_->current_line, comp_id_, "%s.current-line", name);
    r = r ? r : hal_pin_u32_newf(HAL_IN, &pins_->events, comp_id_, "%s.events", name);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &pins_->control_gen, comp_id_, "%s.control-gen", name);
    if (r == 0) {
        *pins_->feed_scale = 1.0;
        *pins_->control_gen = 0;
    }
    r = r ? r : hal_stream_attach(&streams_->blocks, comp_id_, options.block_key, stream::block_types);
    if (r == 0 && options.state_key != 0) {
        r = hal_stream_attach(&streams_->states, comp_id_, options.state_key, stream::state_types);
        streams_->has_states = r == 0;
    }
    if (r != 0) {
        delete streams_;
        hal_exit(comp_id_);
        throw std::runtime_error(std::string(name) + ": cannot create pins or attach to the component's streams "
                                 "(is firtp loaded with the same block_key/state_key?)");
    }
    // Periods already waiting: the component ran before this bridge (one before it was unloaded).
    taking_over_ = streams_->has_states && hal_stream_depth(&streams_->states) > 0;
    sequence_taken_over_ = !taking_over_;
    hal_ready(comp_id_);
    block_subscription_ = lcm.subscribe(messages::block_channel, &Bridge::on_block_bytes, this);
    control_subscription_ = lcm.subscribe(messages::control_channel, &Bridge::on_control_bytes, this);
    event_subscription_ = lcm.subscribe(messages::event_channel, &Bridge::on_event_bytes, this);
    messages::keep_everything(block_subscription_);
    messages::keep_everything(control_subscription_);
    messages::keep_everything(event_subscription_);
}

Bridge::~Bridge() {
    lcm_->unsubscribe(block_subscription_);
    lcm_->unsubscribe(control_subscription_);
    lcm_->unsubscribe(event_subscription_);
    hal_stream_detach(&streams_->blocks);
    if (streams_->has_states) hal_stream_detach(&streams_->states);
    delete streams_;
    hal_exit(comp_id_);
}

void Bridge::report(std::int32_t error, std::string text) {
    status_due_ = true;
    if (fault_ && error_ == firtp_lcm::status_t::ERROR_BAD_VALUE) return;  // keep the cause, not its echoes
    error_ = error;
    error_text_ = std::move(text);
}

std::int64_t Bridge::component_depth() const {
    const std::int64_t depth = std::int64_t{hal_pin::get(pins_->queue_depth)} + hal_stream_depth(&streams_->blocks);
    // Only at rest and in a program this bridge writes whose records the component counts (a
    // halted program's rest is refused uncounted; an abort drops it).
    if (!streams_->has_states || sequence_.program() == 0 || abort_ || fault_ ||
        hal_pin::get(pins_->state) != firtp_lcm::status_t::IDLE)
        return depth;
    const std::int64_t written = sequence_.next_seq() - 1;
    const std::int64_t taken = reported_program_ == sequence_.program() ? reported_next_seq_ - 1 : 0;
    return std::max(depth, written - taken);
}

bool Bridge::component_idle() const {
    return component_depth() == 0 && hal_pin::get(pins_->state) != firtp_lcm::status_t::ABORTING;
}

// The crc first: a corrupted block or event is refused like a lost one (never planned, never
// acknowledged: next_seq stays, the host resends it), and reported, named as far as its bytes allow.
template <class Message>
void Bridge::on_sequenced_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel,
                                void (Bridge::*intact)(const Message*)) {
    const auto received = messages::receive<Message>(buffer->data, buffer->data_size);
    if (!received.problem) return (this->*intact)(&received.message);
    ++rejected_;
    ++corrupted_;
    const std::string name = received.decoded ? messages::describe(received.message)
                                              : channel + " message (" + std::to_string(buffer->data_size) + " bytes)";
    report(firtp_lcm::status_t::ERROR_CORRUPTED,
           name + ": " + *received.problem + "; refused, expected seq " + std::to_string(sequence_.next_seq()));
}

void Bridge::on_block_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    on_sequenced_bytes(buffer, channel, &Bridge::on_block);
}

void Bridge::on_event_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    on_sequenced_bytes(buffer, channel, &Bridge::on_event);
}

// A corrupted control is ignored (the levels in effect stay) and reported; the host republishes
// its controls every control period.
void Bridge::on_control_bytes(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    const auto received = messages::receive<firtp_lcm::control_t>(buffer->data, buffer->data_size);
    if (!received.problem) return on_control(&received.message);
    ++corrupted_;
    const std::string name = received.decoded ? "control seq " + std::to_string(received.message.seq)
                                              : channel + " message (" + std::to_string(buffer->data_size) + " bytes)";
    report(firtp_lcm::status_t::ERROR_CORRUPTED, name + ": " + *received.problem + "; ignored, the controls in effect stay");
}

void Bridge::on_block(const firtp_lcm::block_t* m) {
    if (const auto why = messages::validate(*m)) {
        ++rejected_;
        report(firtp_lcm::status_t::ERROR_BAD_VALUE, *why + "; program stopped");
        fault_ = true;  // the program cannot go on without this block: stop it on the path
        hal_pin::set(pins_->abort, true);
        return;
    }
    if (!admit(m->program, m->seq, messages::describe(*m))) return;
    stream::BlockRecord record;
    record.block = messages::to_block(*m);
    write(record, m->program, m->seq);
}

void Bridge::on_event(const firtp_lcm::event_t* m) {
    if (const auto why = messages::validate(*m)) {
        ++rejected_;
        report(firtp_lcm::status_t::ERROR_BAD_VALUE, *why + "; program stopped");
        fault_ = true;
        hal_pin::set(pins_->abort, true);
        return;
    }
    if (!admit(m->program, m->seq, messages::describe(*m))) return;
    if (reached_ < 0) reached_ = hal_pin::get(pins_->events);
    while (!in_flight_.empty() && in_flight_.front().program != m->program) in_flight_.pop_front();  // never reached
    in_flight_.push_back(*m);
    stream::BlockRecord record;
    record.is_event = true;
    record.event_code = m->kind;
    record.event_value = m->value;
    record.block.line = m->line;
    write(record, m->program, m->seq);
}

bool Bridge::admit(std::int64_t program, std::int64_t seq, const std::string& name) {
    using Verdict = messages::SequenceChecker::Verdict;
    if (taking_over_ && !sequence_taken_over_ && sequence_.program() == 0 &&
        (!period_seen_ || (reported_program_ != 0 && program == reported_program_))) {
        ++rejected_;
        report(firtp_lcm::status_t::ERROR_QUEUE_FULL,
               name + ": taking the program over from the bridge before this one, resend");
        return false;
    }
    const Verdict verdict = sequence_.check(program, seq, component_idle());
    if (verdict != Verdict::accept) {
        ++rejected_;
        const std::int32_t code = verdict == Verdict::repeated
                                      ? std::int32_t{firtp_lcm::status_t::ERROR_REPEATED}
                                      : std::int32_t{firtp_lcm::status_t::ERROR_SEQUENCE_GAP};
        report(code, name + ": " + messages::SequenceChecker::describe(verdict) + ", expected seq " +
                         std::to_string(sequence_.next_seq()));
        return false;
    }
    const bool new_program = program != sequence_.program();
    if (new_program) {
        fault_ = false;
        error_ = 0;
        error_text_.clear();
    }
    if (fault_ || abort_) {
        ++rejected_;
        report(firtp_lcm::status_t::ERROR_SEQUENCE_GAP,
               name + ": refused, the program was " + (abort_ ? "aborted" : "stopped by an error"));
        return false;
    }
    if (!hal_stream_writable(&streams_->blocks)) {
        ++rejected_;
        report(firtp_lcm::status_t::ERROR_QUEUE_FULL, name + ": the block stream is full, resend");
        return false;
    }
    return true;
}

void Bridge::write(const stream::BlockRecord& admitted, std::int64_t program, std::int64_t seq) {
    stream::BlockRecord record = admitted;
    record.program = static_cast<std::uint64_t>(program);  // all 64 bits reach the component
    record.seq = static_cast<std::uint64_t>(seq);
    hal_stream_data buffer[stream::block_elements];
    stream::pack(record, buffer);
    hal_pin::set(pins_->abort, false);
    hal_stream_write(&streams_->blocks, buffer);
    sequence_.accepted(program, seq);
    sequence_taken_over_ = true;  // its own sequence from here: nothing (more) to take over
    ++forwarded_;
}

// Each event the component reached since the last poll, in order, on FIRTP_EVENT_REACHED.
void Bridge::publish_reached() {
    if (reached_ < 0) return;
    const std::uint32_t count = hal_pin::get(pins_->events);
    std::uint32_t fresh = count - static_cast<std::uint32_t>(reached_);
    reached_ = count;
    for (; fresh > 0 && !in_flight_.empty(); --fresh) {
        firtp_lcm::event_t m = in_flight_.front();
        in_flight_.pop_front();
        m.utime = messages::now_utime();
        messages::publish(*lcm_, messages::event_reached_channel, m);
        status_due_ = true;
    }
}

void Bridge::on_control(const firtp_lcm::control_t* m) {
    if (m->session == control_session_ && m->seq <= control_seq_) return;  // older than what is in effect
    if (taking_over_ && !period_seen_) {  // (it took 30, the old bridge's, as not its own)
        if (!waiting_control_ || m->session != waiting_control_->session || m->seq > waiting_control_->seq) waiting_control_ = *m;
        return;
    }
    control_session_ = m->session;  // a new host starts its own count
    control_seq_ = m->seq;
    if (!std::isfinite(m->feed_scale) || m->feed_scale < 0.0) {
        report(firtp_lcm::status_t::ERROR_BAD_VALUE, "control seq " + std::to_string(m->seq) + ": feed_scale " +
                                                         std::to_string(m->feed_scale) + " is not in 0.." +
                                                         std::to_string(options_.max_feed_scale));
    } else {
        feed_scale_ = std::min(m->feed_scale, options_.max_feed_scale);
    }
    hold_ = m->hold;
    abort_ = m->abort;
    inherit_control_gen(hal_pin::get(pins_->control_gen));  // as netted: the signal's value
    // The three levels and the generation that names them, as one (control_pins.hpp); the axis state
    // of every period that applied this generation names this control (forward_states).
    control_gen_ = control_pins::write({pins_->control_gen, pins_->feed_scale, pins_->hold, pins_->abort}, control_gen_,
                                       {feed_scale_, hold_, abort_ || fault_});
    controls_taken_.push_back({control_gen_, m->session, m->seq});
    // Bounded, should firtp.control-gen not be netted (every state names generation 0): should a
    // state still name a generation left out here, name_applied_control reports it.
    if (controls_taken_.size() > max_controls_unapplied) controls_taken_.pop_front();
    status_due_ = true;
}

void Bridge::inherit_control_gen(std::uint32_t gen) {
    if (gen_inherited_) return;
    gen_inherited_ = true;
    inherited_gen_ = gen & ~1u;  // even: a whole generation
    control_gen_ = inherited_gen_;
}

void Bridge::take_over_sequence(std::int64_t tick, const stream::Progress& progress) {
    reported_program_ = static_cast<std::int64_t>(progress.program);
    reported_next_seq_ = static_cast<std::int64_t>(progress.next_seq);
    if (!period_seen_ && !taking_over_ && sequence_.program() == 0 && reported_program_ != 0) {
        taking_over_ = true;  // the first period seen has a program this bridge never wrote
        sequence_taken_over_ = false;
    }
    period_seen_ = true;
    if (sequence_taken_over_ || stream_empty_at_tick_ < 0 || tick <= stream_empty_at_tick_) return;
    sequence_taken_over_ = true;  // this period began after every block written before was taken
    if (sequence_.program() == 0 && reported_program_ != 0) sequence_.accepted(reported_program_, reported_next_seq_ - 1);
}

// The control whose levels the component applied in a period: the one taken as generation `gen`
// (earlier ones were superseded before a period read them). 0: none (or control-gen unconnected).
void Bridge::name_applied_control(std::uint32_t gen) {
    while (!controls_taken_.empty() && static_cast<std::int32_t>(controls_taken_.front().gen - gen) <= 0) {
        applied_control_ = controls_taken_.front();
        controls_taken_.pop_front();
    }
    // Never expected but from the bridge before this one: the pins are not this bridge's.
    if (gen != applied_control_.gen && gen != inherited_gen_ && !unknown_gen_reported_) {
        unknown_gen_reported_ = true;
        report(firtp_lcm::status_t::ERROR_LOST_STATE,
               "the component applied control generation " + std::to_string(gen) +
                   ", which this bridge did not write: axis states name control 0 (is firtp.control-gen netted to " +
                   "another bridge?)");
    }
}

void Bridge::forward_states() {
    if (!streams_->has_states) return;
    hal_stream_data record[stream::state_elements];
    const int progress_group = stream::progress_group(options_.axes);
    // The block stream seen empty while the tick pin is firtp.so's (netted: ahead of every state drained).
    const std::int64_t tick_pin = hal_pin::get(pins_->tick);
    if (!sequence_taken_over_ && stream_empty_at_tick_ < 0 && tick_pin > 0 && tick_pin > last_tick_ &&
        hal_stream_depth(&streams_->blocks) == 0)
        stream_empty_at_tick_ = tick_pin;
    while (hal_stream_read(&streams_->states, record, nullptr) == 0) {
        AxisState& s = streams_->pending;
        const int group = static_cast<int>(record[2].u);
        const std::uint32_t tick32 = record[0].u;
        const bool in_order = group == 0 || (tick32 == streams_->pending_tick && group == streams_->pending_groups);
        streams_->pending_groups = group == progress_group ? 0 : in_order ? group + 1 : 0;
        streams_->pending_tick = tick32;
        for (int i = 0; group < progress_group && i < stream::axes_per_group; ++i) {
            const int a = group * stream::axes_per_group + i;
            if (a >= max_axes) break;
            s.position[a] = record[3 + 3 * i].f;
            s.velocity[a] = record[4 + 3 * i].f;
            s.acceleration[a] = record[5 + 3 * i].f;
        }
        // The period's last record, its progress, completes its axis groups (a period whose
        // groups did not all fit the stream is lost: reported at the next one as a gap in the ticks).
        if (group != progress_group || !in_order) continue;
        const std::int64_t tick =
            last_tick_ < 0 ? tick32 : last_tick_ + static_cast<std::uint32_t>(tick32 - static_cast<std::uint32_t>(last_tick_));
        if (last_tick_ >= 0 && tick != last_tick_ + 1) {
            const std::int64_t gap = tick - last_tick_ - 1;
            lost_states_ += gap;  // the total, as firtp.state-overruns counts them
            report(firtp_lcm::status_t::ERROR_LOST_STATE,
                   std::to_string(lost_states_) + " axis states lost, the latest " + std::to_string(gap) + " before tick " +
                       std::to_string(tick) + " (the bridge fell behind the servo thread)");
        }
        last_tick_ = tick;
        const stream::Progress progress = stream::unpack_progress(record);
        firtp_lcm::axis_state_t m;
        m.utime = messages::now_utime();
        m.tick = tick;
        m.time = static_cast<double>(tick) * options_.period;
        m.line = record[1].s;
        for (int a = 0; a < max_axes; ++a) {
            m.position[a] = s.position[a];
            m.velocity[a] = s.velocity[a];
            m.acceleration[a] = s.acceleration[a];
        }
        m.program = static_cast<std::int64_t>(progress.program);
        m.next_seq = static_cast<std::int64_t>(progress.next_seq);
        inherit_control_gen(progress.control_gen);
        take_over_sequence(tick, progress);
        name_applied_control(progress.control_gen);
        const bool known = progress.control_gen == applied_control_.gen;
        m.control_session = known ? applied_control_.session : 0;
        m.control_seq = known ? applied_control_.seq : 0;
        if (options_.every_period) {
            m.seq = ++state_seq_;
            messages::publish(*lcm_, messages::axis_state_channel, m);
        }
        messages::publish_live(*lcm_, m, options_.live_decimation);
        ++states_;
        if (++periods_since_status_ >= options_.status_every) status_due_ = true;
    }
}

void Bridge::publish_status() {
    // Nothing said before the program is known. Before the first period is read, where the program
    // is the component's, 0 is not known, not "none" (a servo thread stalled while this bridge
    // started, and the host took a second of statuses naming program 0 for the component's
    // restart). Taking over a running program (reported_program_: a period named it), not until
    // the pins are netted and the sequence taken over (an unnetted pin reads 0: idle, an empty
    // queue, as if the program were done).
    if (streams_->has_states && !period_seen_ && sequence_.program() == 0) return;
    if (taking_over_ && !sequence_taken_over_ && reported_program_ != 0) return;
    firtp_lcm::status_t s;
    s.utime = messages::now_utime();
    s.seq = ++status_seq_;
    s.tick = hal_pin::get(pins_->tick);
    const bool own = sequence_.program() != 0;  // else the component's, as its axis states report it
    s.program = own ? sequence_.program() : reported_program_;
    s.next_seq = own ? sequence_.next_seq() : reported_next_seq_;
    s.state = fault_ ? std::int8_t{firtp_lcm::status_t::ERROR} : static_cast<std::int8_t>(hal_pin::get(pins_->state));
    const int stream_depth = hal_stream_depth(&streams_->blocks);
    s.queue_depth = static_cast<std::int32_t>(component_depth());
    s.queue_free = hal_stream_maxdepth(&streams_->blocks) - 1 - stream_depth;
    s.current_line = hal_pin::get(pins_->current_line);
    s.feed_scale = feed_scale_;
    const std::int32_t component_error = hal_pin::get(pins_->error_code);
    if (error_ == 0 && component_error != 0) {
        s.error_code = component_error;
        s.error_text = describe_component_error(component_error);
    } else {
        s.error_code = error_;
        s.error_text = error_text_;
    }
    s.rejected = rejected_ + hal_pin::get(pins_->rejected);
    s.corrupted = corrupted_;
    messages::publish(*lcm_, messages::status_channel, s);
    periods_since_status_ = 0;
    status_due_ = false;
}

void Bridge::poll() {
    forward_states();
    if (waiting_control_ && period_seen_) {
        const firtp_lcm::control_t control = *waiting_control_;
        waiting_control_.reset();
        on_control(&control);
    }
    publish_reached();
    if (status_due_) publish_status();
}

}  // namespace firtp
