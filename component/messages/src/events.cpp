// event_t: program events between blocks, in the blocks' sequence.
#include <firtp/event_kind.hpp>
#include <firtp/messages.hpp>

#include <cmath>

namespace firtp::messages {

// event_t's kinds are firtp::EventKind's values (the program library, the host and firtp.so use those).
static_assert(static_cast<int>(EventKind::spindle_clockwise) == firtp_lcm::event_t::SPINDLE_CLOCKWISE);
static_assert(static_cast<int>(EventKind::spindle_speed) == firtp_lcm::event_t::SPINDLE_SPEED);
static_assert(static_cast<int>(EventKind::tool_change) == firtp_lcm::event_t::TOOL_CHANGE);
static_assert(static_cast<int>(EventKind::pause) == firtp_lcm::event_t::PAUSE);
static_assert(static_cast<int>(EventKind::dwell) == firtp_lcm::event_t::DWELL);
static_assert(static_cast<int>(EventKind::program_end) == firtp_lcm::event_t::PROGRAM_END);
static_assert(event_kinds == firtp_lcm::event_t::PROGRAM_END + 1);

firtp_lcm::event_t event_message(std::int8_t kind, double value, std::int64_t line, std::int64_t program,
                                 std::int64_t seq, std::int64_t utime) {
    firtp_lcm::event_t message{};
    message.utime = utime;
    message.program = program;
    message.seq = seq;
    message.line = static_cast<std::int32_t>(line);
    message.kind = kind;
    message.value = value;
    return message;
}

std::string describe(const firtp_lcm::event_t& message) {
    return "event seq " + std::to_string(message.seq) + " (line " + std::to_string(message.line) + ")";
}

std::optional<std::string> validate(const firtp_lcm::event_t& message) {
    std::string problem;
    if (message.seq < 1) problem = "seq must be >= 1";
    else if (message.kind < firtp_lcm::event_t::SPINDLE_CLOCKWISE || message.kind > firtp_lcm::event_t::PROGRAM_END)
        problem = "unknown kind " + std::to_string(message.kind) + " (0 .. 12, event_t.lcm)";
    else if (!std::isfinite(message.value)) problem = "value is not finite";
    else if (message.kind == firtp_lcm::event_t::DWELL && !(message.value >= 0.0 && message.value <= max_dwell))
        problem = "a dwell of " + std::to_string(message.value) + " s (must be 0 .. " +
                  std::to_string(static_cast<int>(max_dwell)) + ")";
    if (problem.empty()) return std::nullopt;
    return describe(message) + ": " + problem;
}

}  // namespace firtp::messages
