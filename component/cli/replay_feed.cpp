#include "replay_feed.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace firtp::cli {
namespace {

using InputId = std::pair<std::int64_t, std::int64_t>;  // (program, seq) of a block or event, (session, seq) of a control

bool in_sequence(const LoggedEvent& e) {
    return e.channel == messages::block_channel || e.channel == messages::event_channel;
}
bool is_control(const LoggedEvent& e) { return e.channel == messages::control_channel; }

// What the states say was taken: per program, every seq below the highest next_seq; per control
// session, every seq up to the highest control_seq.
struct Taken {
    std::map<std::int64_t, std::int64_t> blocks_until, controls_through;
    explicit Taken(const LoggedRun& run) {
        for (const firtp_lcm::axis_state_t& s : run.states) {
            if (s.next_seq > 1) blocks_until[s.program] = std::max(blocks_until[s.program], s.next_seq);
            if (s.control_seq > 0)
                controls_through[s.control_session] = std::max(controls_through[s.control_session], s.control_seq);
        }
    }
    bool operator()(const LoggedEvent& e) const {
        if (in_sequence(e)) {
            const auto it = blocks_until.find(e.program);
            return it != blocks_until.end() && e.seq < it->second;
        }
        const auto it = controls_through.find(e.program);
        return is_control(e) && it != controls_through.end() && e.seq <= it->second;
    }
};

[[noreturn]] void missing(const firtp_lcm::axis_state_t& s, const LoggedEvent& state_event, const std::string& what) {
    throw std::runtime_error(cat("FIRTP_AXIS_STATE seq ", std::to_string(s.seq), " (log event ",
                                 std::to_string(state_event.eventnum), ") says ", what,
                                 " was taken, but the log does not hold it: start the recorder before the host"));
}

}  // namespace

FeedSchedule feed_schedule(const LoggedRun& run) {
    const Taken taken(run);
    std::map<InputId, const LoggedEvent*> first_block, first_control;  // the first copy of each taken input
    for (const LoggedEvent& e : run.events)
        if (e.kind == LoggedEvent::Kind::input && taken(e))
            (in_sequence(e) ? first_block : first_control).try_emplace(InputId{e.program, e.seq}, &e);

    FeedSchedule schedule;
    schedule.before.resize(run.states.size() + 1);
    std::map<std::int64_t, std::int64_t> fed;             // per program: the seq to feed next
    std::map<std::int64_t, std::int64_t> controls_fed;    // per control session: the highest seq fed
    std::size_t state = 0;                                // states seen so far: the next one's index
    for (const LoggedEvent& e : run.events) {
        if (e.kind == LoggedEvent::Kind::input) {
            if (!taken(e)) schedule.before[state].push_back(&e);
            continue;
        }
        state = e.state;
        const firtp_lcm::axis_state_t& s = run.states[state];
        std::vector<const LoggedEvent*> blocks, controls;
        for (std::int64_t& seq = fed.try_emplace(s.program, 1).first->second; seq < s.next_seq; ++seq) {
            const auto block = first_block.find(InputId{s.program, seq});
            if (block == first_block.end())
                missing(s, e, cat("program ", std::to_string(s.program), " block seq ", std::to_string(seq)));
            blocks.push_back(block->second);
        }
        // The control the period applied, and the ones of its session before it not fed yet: taken by
        // the bridge after the previous period read the pins, each superseded by the next.
        if (std::int64_t& through = controls_fed.try_emplace(s.control_session, 0).first->second;
            s.control_seq > through) {
            if (!first_control.count(InputId{s.control_session, s.control_seq}))
                missing(s, e, cat("control session ", std::to_string(s.control_session), " seq ",
                                  std::to_string(s.control_seq)));
            const auto from = first_control.lower_bound(InputId{s.control_session, through + 1});
            const auto to = first_control.upper_bound(InputId{s.control_session, s.control_seq});
            for (auto it = from; it != to; ++it) controls.push_back(it->second);
            through = s.control_seq;
        }
        // Blocks in their sequence, controls in theirs, the two interleaved as logged (as the bridge
        // most likely received them: an abort taken before a block would refuse it). Each list keeps
        // its own order even where its log order differs (a resend logged after a later seq).
        std::vector<const LoggedEvent*>& inputs = schedule.before[state];
        for (std::size_t b = 0, c = 0; b < blocks.size() || c < controls.size();)
            inputs.push_back(c == controls.size() || (b < blocks.size() && blocks[b]->eventnum < controls[c]->eventnum)
                                 ? blocks[b++]
                                 : controls[c++]);
        schedule.placed_by_state += blocks.size();
        schedule.controls_placed_by_state += controls.size();
        ++state;
    }
    return schedule;
}

}  // namespace firtp::cli
