#include "replay_log.hpp"

#include <firtp/text_cat.hpp>

#include <map>
#include <set>
#include <stdexcept>

namespace firtp::cli {
namespace {

// axis_state_t's fingerprint before control_session and control_seq (program and next_seq were there).
constexpr std::uint64_t axis_state_before_controls = 0xc4dee41eef8eeb16;

// An axis state of that type: refused by name, not only as another fingerprint.
void refuse_old_axis_state(const std::filesystem::path& log, const lcm::LogEvent& event) {
    const auto* bytes = static_cast<const std::uint8_t*>(event.data);
    std::uint64_t fingerprint = 0;
    for (int i = 0; i < 8 && i < event.datalen; ++i) fingerprint = fingerprint << 8 | bytes[i];
    if (event.datalen < 8 || fingerprint != axis_state_before_controls) return;
    throw std::runtime_error(cat(log.string(), ": event ", std::to_string(event.eventnum), " on ", event.channel,
                                 ": an axis_state_t without control_session and control_seq (recorded by a firtp ",
                                 "before they were added): this replay feeds each operator control in the period ",
                                 "those fields name and cannot place the log's controls; record the run again"));
}

template <class Message>
Message intact(const std::filesystem::path& log, const lcm::LogEvent& event) {
    const auto received = messages::receive<Message>(event.data, static_cast<std::size_t>(event.datalen));
    if (received.problem)
        throw std::runtime_error(cat(log.string(), ": event ", std::to_string(event.eventnum), " on ", event.channel,
                                     ": ", *received.problem));
    return received.message;
}

// Every program's blocks, as seen in the log, are 1..highest with nothing missing.
void check_blocks(const std::filesystem::path& log, const std::map<std::int64_t, std::set<std::int64_t>>& programs) {
    for (const auto& [program, seqs] : programs) {
        const std::int64_t highest = *seqs.rbegin();
        if (*seqs.begin() != 1 || static_cast<std::int64_t>(seqs.size()) != highest) {
            std::int64_t first_missing = 1;
            while (seqs.count(first_missing)) ++first_missing;
            throw std::runtime_error(cat(log.string(), ": program ", std::to_string(program), " misses ",
                                         std::to_string(highest - static_cast<std::int64_t>(seqs.size())),
                                         " of its blocks 1..", std::to_string(highest), " (first: seq ",
                                         std::to_string(first_missing),
                                         "): the log is incomplete; record with `firtp record`, started before the host"));
        }
    }
}

void check_states(const std::filesystem::path& log, const LoggedRun& run) {
    for (std::size_t i = 1; i < run.states.size(); ++i) {
        const std::int64_t missing = run.states[i].seq - run.states[i - 1].seq - 1;
        if (missing == 0) continue;
        const std::string what = missing > 0 ? cat(std::to_string(missing), " axis states missing before")
                                             : std::string("a repeated or reordered axis state at");
        throw std::runtime_error(cat(log.string(), ": ", what, " FIRTP_AXIS_STATE seq ", std::to_string(run.states[i].seq),
                                     " (event ", std::to_string(run.state_events[i]),
                                     "): the log is incomplete; record with `firtp record`"));
    }
}

}  // namespace

LoggedRun read_logged_run(const std::filesystem::path& log) {
    if (!std::filesystem::is_regular_file(log)) throw std::runtime_error(cat("no log file '", log.string(), "'"));
    lcm::LogFile file(log.string(), "r");
    if (!file.good()) throw std::runtime_error(cat("cannot read the LCM log '", log.string(), "'"));
    LoggedRun run;
    std::map<std::int64_t, std::set<std::int64_t>> programs;
    while (const lcm::LogEvent* event = file.readNextEvent()) {
        const std::string& channel = event->channel;
        if (channel == messages::config_channel) {
            if (!run.config) run.config = intact<firtp_lcm::config_t>(log, *event);
        } else if (channel == messages::block_channel || channel == messages::event_channel ||
                   channel == messages::control_channel) {
            LoggedEvent e;
            e.eventnum = event->eventnum;
            e.channel = channel;
            if (channel == messages::block_channel) {
                const auto block = intact<firtp_lcm::block_t>(log, *event);
                programs[block.program].insert(block.seq);
                e.program = block.program;
                e.seq = block.seq;
                ++run.blocks;
            } else if (channel == messages::event_channel) {  // in the blocks' sequence
                const auto program_event = intact<firtp_lcm::event_t>(log, *event);
                programs[program_event.program].insert(program_event.seq);
                e.program = program_event.program;
                e.seq = program_event.seq;
                ++run.program_events;
            } else {  // controls: their own sequence per session
                const auto control = intact<firtp_lcm::control_t>(log, *event);
                e.program = control.session;
                e.seq = control.seq;
                ++run.controls;
            }
            const auto* bytes = static_cast<const std::uint8_t*>(event->data);
            e.data.assign(bytes, bytes + event->datalen);
            run.events.push_back(std::move(e));
        } else if (channel == messages::status_channel) {
            run.statuses.push_back(intact<firtp_lcm::status_t>(log, *event));
        } else if (channel == messages::axis_state_channel) {
            LoggedEvent e;
            e.kind = LoggedEvent::Kind::state;
            e.eventnum = event->eventnum;
            e.state = run.states.size();
            refuse_old_axis_state(log, *event);
            run.states.push_back(intact<firtp_lcm::axis_state_t>(log, *event));
            run.state_events.push_back(event->eventnum);
            run.events.push_back(std::move(e));
        }
    }
    if (run.blocks == 0) throw std::runtime_error(cat(log.string(), ": no FIRTP_BLOCK in the log: nothing to replay"));
    if (run.states.empty()) throw std::runtime_error(cat(log.string(), ": no FIRTP_AXIS_STATE in the log: nothing to compare"));
    check_blocks(log, programs);
    check_states(log, run);
    return run;
}

}  // namespace firtp::cli
