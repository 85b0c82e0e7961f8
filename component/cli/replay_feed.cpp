#include "replay_feed.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace firtp::cli {
namespace {

using BlockId = std::pair<std::int64_t, std::int64_t>;  // program, seq

// Per program: every seq below this was taken by the recorded component.
std::map<std::int64_t, std::int64_t> taken_until(const LoggedRun& run) {
    std::map<std::int64_t, std::int64_t> until;
    for (const firtp_lcm::axis_state_t& s : run.states)
        if (s.next_seq > 1) until[s.program] = std::max(until[s.program], s.next_seq);
    return until;
}

}  // namespace

FeedSchedule feed_schedule(const LoggedRun& run) {
    const auto until = taken_until(run);
    const auto taken = [&](const LoggedEvent& e) {
        const auto it = until.find(e.program);
        return (e.channel == messages::block_channel || e.channel == messages::event_channel) && it != until.end() &&
               e.seq < it->second;
    };
    std::map<BlockId, const LoggedEvent*> first_copy;
    for (const LoggedEvent& e : run.events)
        if (e.kind == LoggedEvent::Kind::input && taken(e)) first_copy.try_emplace(BlockId{e.program, e.seq}, &e);

    FeedSchedule schedule;
    schedule.before.resize(run.states.size() + 1);
    std::map<std::int64_t, std::int64_t> fed;  // per program: the seq to feed next
    std::size_t state = 0;                     // states seen so far: the next one's index
    for (const LoggedEvent& e : run.events) {
        if (e.kind == LoggedEvent::Kind::input) {
            if (!taken(e)) schedule.before[state].push_back(&e);
            continue;
        }
        state = e.state;
        const firtp_lcm::axis_state_t& s = run.states[state];
        for (std::int64_t& seq = fed.try_emplace(s.program, 1).first->second; seq < s.next_seq; ++seq) {
            const auto block = first_copy.find(BlockId{s.program, seq});
            if (block == first_copy.end())
                throw std::runtime_error(cat("FIRTP_AXIS_STATE seq ", std::to_string(s.seq), " (log event ",
                                             std::to_string(e.eventnum), ") says program ", std::to_string(s.program),
                                             " block seq ", std::to_string(seq),
                                             " was taken, but the log does not hold it: start the recorder before the host"));
            schedule.before[state].push_back(block->second);
            ++schedule.placed_by_state;
        }
        ++state;
    }
    return schedule;
}

}  // namespace firtp::cli
