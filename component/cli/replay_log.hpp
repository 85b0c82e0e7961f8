// What `firtp replay` takes from an LCM log: the component's configuration, and in log order the
// messages sent to it (blocks, program events, controls) and the axis states it produced. Every message must be
// intact and the log complete (no axis state or block missing), else it cannot be replayed.
#pragma once

#include <firtp/messages.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace firtp::cli {

struct LoggedEvent {
    enum class Kind { input, state } kind = Kind::input;
    std::int64_t eventnum = 0;
    std::string channel;                     // input: FIRTP_BLOCK, FIRTP_EVENT or FIRTP_CONTROL
    std::vector<std::uint8_t> data;          // input: the bytes as logged (sealed)
    std::int64_t program = 0, seq = 0;       // input on FIRTP_BLOCK or FIRTP_EVENT: its place in the sequence;
                                             // on FIRTP_CONTROL: its session (in program) and seq
    std::size_t state = 0;                   // state: index into LoggedRun::states
};

struct LoggedRun {
    std::optional<firtp_lcm::config_t> config;  // the run's first FIRTP_CONFIG
    std::int64_t first_event = 0, last_event = 0;  // the log events it spans
    // States where its publisher started again while the component ran on (firtp-lcm-bridge
    // restarted under firtp.so: same machine, ticks consecutive, seq from 1): one run of the component.
    std::vector<std::size_t> bridge_restarts;
    std::vector<LoggedEvent> events;
    std::vector<firtp_lcm::axis_state_t> states;  // FIRTP_AXIS_STATE, in log order
    std::vector<std::int64_t> state_events;       // their event numbers
    std::vector<firtp_lcm::status_t> statuses;    // FIRTP_STATUS, in log order
    std::int64_t blocks = 0, program_events = 0, controls = 0;
};

// The runs of the component in a log, in order: a run starts again where FIRTP_CONFIG's seq does
// (its publisher started again: `firtp serve` run twice, LinuxCNC restarted), except where the
// publisher was only firtp-lcm-bridge restarted under a running firtp.so (the same machine, the
// ticks going on): that stays one run (bridge_restarts).
// `only` (1-based): read and check that run alone. Throws std::runtime_error naming the log, the
// event and, in a log of several runs, the run: unreadable, a corrupted message, axis states
// missing (seq gaps) or starting again without a new FIRTP_CONFIG, a run whose first axis state is
// not its component's first period (tick 0) and names blocks or controls taken before (its state
// then is not in the log), a
// program whose blocks do not start at seq 1 or have gaps, axis states of the type before they
// named the control applied in their period (control_session, control_seq): such logs are refused,
// the replay could not place the controls (docs/RECORDING.md).
std::vector<LoggedRun> read_logged_runs(const std::filesystem::path& log, std::optional<int> only = {});

// A log of one run (throws naming the runs when it holds several).
LoggedRun read_logged_run(const std::filesystem::path& log);

}  // namespace firtp::cli
