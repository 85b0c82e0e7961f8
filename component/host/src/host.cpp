#include <firtp/host.hpp>

#include "axis_recorder.hpp"
#include "block_stream.hpp"
#include "control_sender.hpp"
#include "status_watch.hpp"

#include <firtp/messages.hpp>

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <utility>

namespace firtp::host {
namespace {

using firtp_lcm::status_t;

constexpr int max_messages_per_step = 10000;  // step() never spins forever on a flood
// Statuses that name another program for this long after ours was seen: the component has lost
// ours (it restarted, or another host's program replaced it). A late status from before ours
// started is a one-off and does not last this long.
constexpr auto lost_program_after = std::chrono::seconds(1);


// One message to send: a block or an event (seq i at index i - 1, in program order).
struct Outgoing {
    bool is_event = false;
    firtp_lcm::block_t block{};
    firtp_lcm::event_t event{};
};

// The program's messages in seq order: the events before block i, then block i; the events after
// the last block at the end.
class Records {
public:
    Records(const ProgramFeed& feed, std::int64_t program_id) : feed_(feed), blocks_(feed.read()), program_(program_id) {}

    bool next(Outgoing& o) {
        const std::int64_t seq = seq_ + 1;
        o = Outgoing{};
        if (event_ < feed_.events.size() && feed_.events[event_].before_block <= block_) {
            const ProgramEvent& e = feed_.events[event_++];
            o.is_event = true;
            o.event = messages::event_message(static_cast<std::int8_t>(e.kind), e.value, e.line, program_, seq, 0);
        } else if (block_ < feed_.blocks) {
            Block b;
            if (!blocks_->next(b)) throw std::logic_error("host: the program has fewer blocks than it said");
            ++block_;
            o.block = messages::to_message(b, program_, seq, 0);
        } else {
            return false;
        }
        seq_ = seq;
        return true;
    }

private:
    const ProgramFeed& feed_;
    std::unique_ptr<BlockPuller> blocks_;
    std::int64_t program_;
    std::int64_t seq_ = 0;
    std::size_t event_ = 0, block_ = 0;
};

std::int64_t records(const ProgramFeed& program) { return std::ssize(program.events) + static_cast<std::int64_t>(program.blocks); }

// A program's blocks, the program kept alive as long as it reads them.
class ProgramPuller : public SpanPuller {
public:
    explicit ProgramPuller(std::shared_ptr<const Program> program) : SpanPuller(program->blocks), program_(std::move(program)) {}

private:
    std::shared_ptr<const Program> program_;
};

}  // namespace

ProgramFeed feed_of(std::shared_ptr<const Program> program) {
    ProgramFeed feed;
    feed.blocks = program->blocks.size();
    feed.events = program->events;
    feed.read = [program] { return std::make_unique<ProgramPuller>(program); };
    return feed;
}

const char* to_string(Result result) {
    switch (result) {
        case Result::running: return "running";
        case Result::done: return "done";
        case Result::failed: return "failed";
        case Result::lost: return "lost contact";
        case Result::aborted: return "aborted";
    }
    return "?";
}

const char* state_name(int state) {
    switch (state) {
        case status_t::IDLE: return "idle";
        case status_t::MOVING: return "moving";
        case status_t::HOLDING: return "holding";
        case status_t::ABORTING: return "aborting";
        case status_t::ERROR: return "error";
        case status_t::DISABLED: return "disabled";
        case -1: return "waiting";
    }
    return "unknown";
}

struct Host::State {
    State(lcm::LCM& l, const ProgramFeed& program, HostOptions o)
        : lcm(l),
          options(std::move(o)),
          program_id(options.program_id != 0 ? options.program_id : messages::now_utime()),
          feed(program),
          stream(program_id, records(feed),
                 {options.initial_window, options.resend_timeout, options.max_resends}),
          control(program_id, options.feed_scale, options.max_feed_scale, options.control_period),
          axes(options.record_axis_states),
          watch(program_id, records(feed)) {
        // Every message checked before anything is sent; then read again as they go out.
        Records check(feed, program_id);
        for (Outgoing m; check.next(m);) {
            const auto problem = m.is_event ? messages::validate(m.event) : messages::validate(m.block);
            if (problem) {
                finish(Result::failed, *problem);
                break;
            }
        }
        reader.emplace(feed, program_id);
        moves = feed.blocks;
    }

    Clock::time_point now() const { return options.clock ? options.clock() : Clock::now(); }

    // A status or axis state whose crc does not match is dropped, as if lost: the next intact
    // one replaces it (a status says everything again; axis states show the gap in their seq).
    void on_status_bytes(const lcm::ReceiveBuffer* buffer, const std::string&) {
        const auto received = messages::receive<status_t>(buffer->data, buffer->data_size);
        if (received.problem) {
            ++statistics.corrupted_dropped;
            return;
        }
        on_status(&received.message);
    }

    void on_axis_state_bytes(const lcm::ReceiveBuffer* buffer, const std::string&) {
        const auto received = messages::receive<firtp_lcm::axis_state_t>(buffer->data, buffer->data_size);
        if (received.problem) {
            ++statistics.corrupted_dropped;
            return;
        }
        axes.on_message(received.message);
        if (options.on_axis_state) options.on_axis_state(received.message);
    }

    void on_reached_bytes(const lcm::ReceiveBuffer* buffer, const std::string&) {
        const auto received = messages::receive<firtp_lcm::event_t>(buffer->data, buffer->data_size);
        if (received.problem) {
            ++statistics.corrupted_dropped;
            return;
        }
        if (received.message.program != program_id) return;
        ++statistics.events_reached;
        if (options.on_event_reached) options.on_event_reached(received.message);
    }

    void on_status(const status_t* status) {
        const Clock::time_point t = now();
        ++statistics.statuses;
        last_status = t;
        if (!latest) {
            rejected_before = status->rejected;
            corrupted_before = status->corrupted;
        }
        statistics.rejected = status->rejected - rejected_before;
        statistics.corrupted_refused = status->corrupted - corrupted_before;
        latest = *status;
        stream.on_status(*status, t);
        if (result != Result::running) return;
        const Result judged = watch.on_status(*status, aborting);
        if (judged != Result::running) return finish(judged, watch.error());
        if (status->program == program_id) {
            seen_ours = true;
            other_program_since.reset();
        } else if (seen_ours && !aborting) {
            if (!other_program_since) other_program_since = t;
            if (t - *other_program_since >= lost_program_after)
                finish(Result::failed, "the component no longer has program " + std::to_string(program_id) +
                                           " (its status has named program " + std::to_string(status->program) +
                                           " for " + std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                                                        t - *other_program_since).count()) +
                                           " ms): it restarted, or another program replaced it; block seq " +
                                           std::to_string(stream.acknowledged() + 1) + " was next");
        }
    }

    void finish(Result r, std::string text) {
        result = r;
        error = std::move(text);
        if (r == Result::aborted) {  // stopped and empty: let the next program in
            control.set_abort(false);
            control.set_hold(false);
            publish_control(now());
        }
    }

    void publish_control(Clock::time_point t) {
        if (auto message = control.due(t, messages::now_utime())) {
            messages::publish(lcm, messages::control_channel, *message);
            ++statistics.controls;
        }
    }

    // The message of `seq`, read from the program when first asked for: seq from the oldest one
    // not yet acknowledged at the latest forget_acknowledged() on.
    Outgoing& record(std::int64_t seq) {
        while (window_first + std::ssize(window) <= seq) {
            Outgoing o;
            if (!reader->next(o)) throw std::logic_error("host: seq beyond the program");
            window.push_back(std::move(o));
        }
        return window[static_cast<std::size_t>(seq - window_first)];
    }

    // Not before check_stall() of the same step: the stalled seq may have been acknowledged since.
    void forget_acknowledged() {
        for (; !window.empty() && window_first <= stream.acknowledged(); ++window_first) window.pop_front();
    }

    void publish_blocks(Clock::time_point t) {
        forget_acknowledged();
        for (int n = 0; n < options.max_burst; ++n) {
            const std::optional<std::int64_t> seq = stream.next();
            if (!seq) return;
            Outgoing& o = record(*seq);
            if (o.is_event) {
                o.event.utime = messages::now_utime();
                messages::publish(lcm, messages::event_channel, o.event);  // sealed after the utime
                ++statistics.events_published;
            } else {
                o.block.utime = messages::now_utime();
                messages::publish(lcm, messages::block_channel, o.block);
                ++statistics.blocks_published;
            }
            stream.sent(*seq, t);
        }
    }

    void check_stall() {
        const std::optional<std::int64_t> seq = stream.stalled();
        if (!seq) return;
        const Outgoing& o = record(*seq);
        std::string text = (o.is_event ? messages::describe(o.event) : messages::describe(o.block)) + " not accepted after " +
                           std::to_string(options.max_resends) + " resends";
        if (latest && !latest->error_text.empty()) text += "; component: " + latest->error_text;
        finish(Result::failed, text);
    }

    lcm::LCM& lcm;
    HostOptions options;
    std::int64_t program_id;
    ProgramFeed feed;                 // its reader's view of the program
    std::optional<Records> reader;    // what to send next, read as it goes
    std::deque<Outgoing> window;      // seq window_first on: sent or about to be, not known acknowledged
    std::int64_t window_first = 1;
    std::size_t moves = 0;            // blocks among the messages
    BlockStream stream;
    ControlSender control;
    AxisRecorder axes;
    StatusWatch watch;
    lcm::Subscription* status_subscription = nullptr;
    lcm::Subscription* axis_subscription = nullptr;
    lcm::Subscription* reached_subscription = nullptr;
    Result result = Result::running;
    std::string error;
    Statistics statistics;
    std::optional<status_t> latest;
    std::int64_t rejected_before = 0;   // status rejected count when this host started
    std::int64_t corrupted_before = 0;  // status corrupted count then
    bool started = false;
    bool aborting = false;
    bool seen_ours = false;                                 // a status has named this program
    std::optional<Clock::time_point> other_program_since;  // since when statuses name another
    Clock::time_point last_status{};    // or the first step, before any status
};

Host::Host(lcm::LCM& lcm, const Program& program, HostOptions options)
    : Host(lcm, feed_of(std::make_shared<const Program>(program)), std::move(options)) {}

Host::Host(lcm::LCM& lcm, const ProgramFeed& program, HostOptions options)
    : state_(std::make_unique<State>(lcm, program, std::move(options))) {
    State& s = *state_;
    s.status_subscription = lcm.subscribe(messages::status_channel, &State::on_status_bytes, &s);
    messages::keep_everything(s.status_subscription);
    s.axis_subscription = lcm.subscribe(messages::axis_state_channel, &State::on_axis_state_bytes, &s);
    messages::keep_everything(s.axis_subscription);
    s.reached_subscription = lcm.subscribe(messages::event_reached_channel, &State::on_reached_bytes, &s);
    messages::keep_everything(s.reached_subscription);
}

Host::~Host() {
    state_->lcm.unsubscribe(state_->status_subscription);
    state_->lcm.unsubscribe(state_->axis_subscription);
    state_->lcm.unsubscribe(state_->reached_subscription);
}

Result Host::step() {
    State& s = *state_;
    if (s.result != Result::running) return s.result;
    if (s.moves == 0) {  // nothing moves: done, as before events were sent
        s.finish(Result::done, "");
        return s.result;
    }
    if (!s.started) {
        s.started = true;
        s.last_status = s.now();
    }
    for (int n = 0; n < max_messages_per_step && s.lcm.handleTimeout(0) > 0; ++n) {}
    if (s.result != Result::running) return s.result;

    const Clock::time_point t = s.now();
    if (t - s.last_status >= s.options.status_timeout) {
        const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(s.options.status_timeout);
        s.finish(Result::lost, "no status from the component for " + std::to_string(ms.count()) + " ms");
        return s.result;
    }
    s.stream.on_time(t);
    s.check_stall();
    if (s.result != Result::running) return s.result;
    if (!s.aborting) s.publish_blocks(t);
    s.publish_control(t);
    return s.result;
}

Result Host::run(std::stop_token stop, std::optional<Clock::time_point> deadline) {
    for (;;) {
        const Result r = step();
        if (r != Result::running || stop.stop_requested()) return r;
        if (deadline && state_->now() >= *deadline) return r;
        state_->lcm.handleTimeout(10);
    }
}

void Host::set_feed_scale(double scale) {
    if (state_->result != Result::running) return;
    state_->control.set_feed_scale(scale);
    state_->publish_control(state_->now());
}

void Host::hold(bool on) {
    if (state_->result != Result::running) return;
    state_->control.set_hold(on);
    state_->publish_control(state_->now());
}

void Host::abort() {
    if (state_->result != Result::running) return;
    state_->aborting = true;
    state_->control.set_abort(true);
    state_->publish_control(state_->now());
}

Result Host::result() const { return state_->result; }
const std::string& Host::error() const { return state_->error; }
Statistics Host::statistics() const {
    Statistics statistics = state_->statistics;
    statistics.go_backs = state_->stream.go_backs();
    statistics.axis_states = state_->axes.received();
    statistics.axis_states_lost = state_->axes.lost();
    return statistics;
}
std::int64_t Host::program_id() const { return state_->program_id; }
double Host::max_feed_scale() const { return state_->control.max_feed_scale(); }
std::string Host::axis_state_gap_text() const { return state_->axes.gap_text(); }
const std::vector<firtp_lcm::axis_state_t>& Host::axis_states() const { return state_->axes.messages(); }

Progress Host::progress() const {
    const State& s = *state_;
    Progress p;
    p.blocks = static_cast<std::size_t>(records(s.feed));
    p.sent = static_cast<std::size_t>(s.stream.highest_sent());
    p.acknowledged = static_cast<std::size_t>(s.stream.acknowledged());
    p.feed_request = s.control.feed_scale();
    p.feed_in_effect = p.feed_request;
    p.hold = s.control.hold();
    p.abort = s.aborting;
    if (s.latest) {
        const status_t& status = *s.latest;
        p.line = status.current_line;
        p.state = status.state;
        p.feed_in_effect = status.feed_scale;
        if (status.program == s.program_id)
            p.executed = static_cast<std::size_t>(std::max<std::int64_t>(status.next_seq - 1 - status.queue_depth, 0));
    }
    if (s.result == Result::done) p.executed = p.blocks;
    return p;
}

}  // namespace firtp::host
