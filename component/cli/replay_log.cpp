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
using Programs = std::map<std::int64_t, std::set<std::int64_t>>;  // the seqs seen of each program

void check_blocks(const std::string& where, const Programs& programs) {
    for (const auto& [program, seqs] : programs) {
        const std::int64_t highest = *seqs.rbegin();
        if (*seqs.begin() != 1 || static_cast<std::int64_t>(seqs.size()) != highest) {
            std::int64_t first_missing = 1;
            while (seqs.count(first_missing)) ++first_missing;
            throw std::runtime_error(cat(where, ": program ", std::to_string(program), " misses ",
                                         std::to_string(highest - static_cast<std::int64_t>(seqs.size())),
                                         " of its blocks 1..", std::to_string(highest), " (first: seq ",
                                         std::to_string(first_missing),
                                         "): the log is incomplete; record with `firtp record`, started before the host"));
        }
    }
}

void check_states(const std::string& where, const LoggedRun& run) {
    // Logged from a later period (a recorder started a little after the component) is replayable
    // while the component has taken nothing yet: the replay runs the periods before unchecked.
    const firtp_lcm::axis_state_t& first = run.states.front();
    if (first.tick != 0 && (first.program != 0 || first.next_seq != 1 || first.control_session != 0))
        throw std::runtime_error(cat(where, ": its first axis state (FIRTP_AXIS_STATE seq ", std::to_string(first.seq),
                                     ", event ", std::to_string(run.state_events.front()), ") is tick ",
                                     std::to_string(first.tick), " of a component that had taken blocks or controls ",
                                     "before (the recorder started late, or firtp-lcm-bridge was restarted under a ",
                                     "running firtp.so), and its state then is not in the log; record from the ",
                                     "component's start"));
    for (std::size_t i = 1, join = 0; i < run.states.size(); ++i) {
        const std::int64_t missing = run.states[i].seq - run.states[i - 1].seq - 1;
        const bool restarted = join < run.bridge_restarts.size() && run.bridge_restarts[join] == i;
        if (restarted) ++join;
        if (missing == 0 || (restarted && run.states[i].seq == 1)) continue;
        const std::string at = cat(" FIRTP_AXIS_STATE seq ", std::to_string(run.states[i].seq), " (event ",
                                   std::to_string(run.state_events[i]), ")");
        if (run.states[i].seq == 1)
            throw std::runtime_error(cat(where, ": the axis states start again at", at, " without a new FIRTP_CONFIG: ",
                                         "a restarted component that does not publish its machine; record each run ",
                                         "into its own log"));
        const std::string what = missing > 0 ? cat(std::to_string(missing), " axis states missing before")
                                             : std::string("a repeated or reordered axis state at");
        throw std::runtime_error(cat(where, ": ", what, at, ": the log is incomplete; record with `firtp record`"));
    }
}

// A run as it is read, with its programs' seqs.
struct RunReader {
    LoggedRun run;
    Programs programs;
    std::int64_t config_seq = 0;  // the last FIRTP_CONFIG's
    bool empty() const { return run.events.empty(); }
};

bool same_machine(const firtp_lcm::config_t& a, const firtp_lcm::config_t& b) {
    const bool by_args = a.command == "loadrt";  // firtp.so's words; its INI is only for the reader
    return a.command == b.command && a.args == b.args &&
           (by_args || (a.ini_file == b.ini_file && a.ini_text == b.ini_text)) &&
           a.queue == b.queue && a.max_blocks == b.max_blocks && a.stream_depth == b.stream_depth &&
           a.plan_budget_us == b.plan_budget_us && a.period == b.period && a.axes == b.axes;
}

// `next` goes on where `run` ended: its publisher (firtp-lcm-bridge) started again, the component
// (firtp.so) ran on with the same machine, its ticks consecutive.
bool continues(const RunReader& run, const RunReader& next) {
    const LoggedRun &a = run.run, &b = next.run;
    return a.config && b.config && same_machine(*a.config, *b.config) && !a.states.empty() && !b.states.empty() &&
           b.states.front().tick == a.states.back().tick + 1;
}

void append(RunReader& run, RunReader&& next) {
    LoggedRun &a = run.run, &b = next.run;
    const std::size_t offset = a.states.size();
    a.bridge_restarts.push_back(offset);
    for (LoggedEvent& e : b.events) {
        if (e.kind == LoggedEvent::Kind::state) e.state += offset;
        a.events.push_back(std::move(e));
    }
    a.states.insert(a.states.end(), b.states.begin(), b.states.end());
    // The new bridge names the previous one's control generation 0, 0 (it cannot know it) until a
    // control of its own is applied: that is the control last named before the restart.
    const firtp_lcm::axis_state_t before = a.states[offset - 1];
    for (std::size_t i = offset; i < a.states.size() && a.states[i].control_seq == 0; ++i) {
        a.states[i].control_session = before.control_session;
        a.states[i].control_seq = before.control_seq;
    }
    a.state_events.insert(a.state_events.end(), b.state_events.begin(), b.state_events.end());
    a.statuses.insert(a.statuses.end(), b.statuses.begin(), b.statuses.end());
    a.blocks += b.blocks;
    a.program_events += b.program_events;
    a.controls += b.controls;
    a.last_event = b.last_event;
    for (auto& [program, seqs] : next.programs) run.programs[program].insert(seqs.begin(), seqs.end());
}

}  // namespace

std::vector<LoggedRun> read_logged_runs(const std::filesystem::path& log, std::optional<int> only) {
    if (!std::filesystem::is_regular_file(log)) throw std::runtime_error(cat("no log file '", log.string(), "'"));
    lcm::LogFile file(log.string(), "r");
    if (!file.good()) throw std::runtime_error(cat("cannot read the LCM log '", log.string(), "'"));
    std::vector<RunReader> runs(1);
    while (const lcm::LogEvent* event = file.readNextEvent()) {
        const std::string& channel = event->channel;
        if (channel == messages::config_channel) {
            const auto config = intact<firtp_lcm::config_t>(log, *event);
            RunReader* r = &runs.back();
            if (r->run.config && config.seq <= r->config_seq) {  // its publisher started again
                if (!r->empty()) r = &runs.emplace_back();
                r->run.config.reset();  // a config before anything else is replaced (record --ini, then serve's own)
            }
            if (!r->run.config) {
                r->run.config = config;
                if (r->empty()) r->run.first_event = event->eventnum;
            }
            r->config_seq = config.seq;
            r->run.last_event = event->eventnum;
            continue;
        }
        RunReader& r = runs.back();
        LoggedRun& run = r.run;
        if (channel == messages::block_channel || channel == messages::event_channel ||
            channel == messages::control_channel) {
            LoggedEvent e;
            e.eventnum = event->eventnum;
            e.channel = channel;
            if (channel == messages::block_channel) {
                const auto block = intact<firtp_lcm::block_t>(log, *event);
                r.programs[block.program].insert(block.seq);
                e.program = block.program;
                e.seq = block.seq;
                ++run.blocks;
            } else if (channel == messages::event_channel) {  // in the blocks' sequence
                const auto program_event = intact<firtp_lcm::event_t>(log, *event);
                r.programs[program_event.program].insert(program_event.seq);
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
            if (r.empty() && !run.config) run.first_event = event->eventnum;
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
            if (r.empty() && !run.config) run.first_event = event->eventnum;
            run.events.push_back(std::move(e));
        } else {
            continue;
        }
        run.last_event = event->eventnum;
    }
    for (std::size_t k = 1; k < runs.size();) {
        if (continues(runs[k - 1], runs[k])) {
            append(runs[k - 1], std::move(runs[k]));
            runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(k));
        } else {
            ++k;
        }
    }
    const int count = static_cast<int>(runs.size());
    if (only && (*only < 1 || *only > count))
        throw std::runtime_error(cat(log.string(), " holds ", std::to_string(count), count == 1 ? " run" : " runs",
                                     " of the component, not a run ", std::to_string(*only)));
    std::vector<LoggedRun> out;
    for (int k = 1; k <= count; ++k) {
        if (only && k != *only) continue;
        RunReader& r = runs[static_cast<std::size_t>(k - 1)];
        const std::string where =
            count == 1 ? log.string()
                       : cat(log.string(), ", run ", std::to_string(k), " of ", std::to_string(count), " (log events ",
                             std::to_string(r.run.first_event), "-", std::to_string(r.run.last_event), ")");
        // Without a machine or a block (LinuxCNC's own motion: firtp-lcm-bridge --mode motion, its
        // states from tick 1) there is nothing to replay, said below.
        if (!r.run.states.empty() && (r.run.config || r.run.blocks > 0)) check_states(where, r.run);
        if (r.run.blocks == 0) throw std::runtime_error(cat(where, ": no FIRTP_BLOCK in the log: nothing to replay"));
        if (r.run.states.empty()) throw std::runtime_error(cat(where, ": no FIRTP_AXIS_STATE in the log: nothing to compare"));
        check_blocks(where, r.programs);
        out.push_back(std::move(r.run));
    }
    return out;
}

LoggedRun read_logged_run(const std::filesystem::path& log) {
    std::vector<LoggedRun> runs = read_logged_runs(log);
    if (runs.size() != 1)
        throw std::runtime_error(cat(log.string(), " holds ", std::to_string(runs.size()), " runs of the component"));
    return std::move(runs.front());
}

}  // namespace firtp::cli
