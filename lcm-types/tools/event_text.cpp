#include "event_text.hpp"

#include <type_traits>

#include <firtp/messages.hpp>

#include <charconv>
#include <concepts>

namespace firtp::dump {
namespace {

// Shortest text that reads back to the same double.
std::string number(double value) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return std::string(buffer, end);
}

const char* state_name(std::int8_t state) {
    switch (state) {
        case firtp_lcm::status_t::IDLE: return "idle";
        case firtp_lcm::status_t::MOVING: return "moving";
        case firtp_lcm::status_t::HOLDING: return "holding";
        case firtp_lcm::status_t::ABORTING: return "aborting";
        case firtp_lcm::status_t::ERROR: return "error";
        case firtp_lcm::status_t::DISABLED: return "disabled";
        default: return "unknown";
    }
}

// "type name=value name=value ...", built by appending.
class Line {
public:
    explicit Line(const char* type) : text_(type) {}
    template <std::integral Integer> Line& field(const char* name, Integer value) {
        return raw(name, std::to_string(static_cast<std::int64_t>(value)));
    }
    Line& field(const char* name, double value) { return raw(name, number(value)); }
    Line& field(const char* name, const char* value) { return raw(name, value); }
    Line& xyz(const char* name, const double (&axes)[9]) {
        std::string value = "(";
        value.append(number(axes[0])).append(",").append(number(axes[1])).append(",").append(number(axes[2]));
        return raw(name, value.append(")"));
    }
    Line& quoted(const std::string& value) {
        if (!value.empty()) text_.append(" \"").append(value).append("\"");
        return *this;
    }
    std::string str() const { return text_; }

private:
    Line& raw(const char* name, const std::string& value) {
        text_.append(" ").append(name).append("=").append(value);
        return *this;
    }
    std::string text_;
};

std::string text(const firtp_lcm::block_t& m) {
    return Line("block_t").field("seq", m.seq).field("program", m.program).field("line", m.line)
        .xyz("target", m.target).field("feed", m.feed).field("tolerance", m.tolerance).str();
}

std::string text(const firtp_lcm::status_t& m) {
    return Line("status_t").field("seq", m.seq).field("program", m.program).field("next_seq", m.next_seq)
        .field("state", state_name(m.state))
        .field("queue", m.queue_depth).field("free", m.queue_free).field("error", m.error_code)
        .quoted(m.error_text).str();
}

std::string text(const firtp_lcm::axis_state_t& m) {
    return Line("axis_state_t").field("seq", m.seq).field("tick", m.tick).field("line", m.line)
        .xyz("position", m.position).field("program", m.program).field("next_seq", m.next_seq).str();
}

std::string text(const firtp_lcm::control_t& m) {
    return Line("control_t").field("seq", m.seq).field("feed_scale", m.feed_scale).field("hold", m.hold)
        .field("abort", m.abort).str();
}

std::string text(const firtp_lcm::config_t& m) {
    return Line("config_t").field("seq", m.seq).field("command", m.command.c_str())
        .field("ini", m.ini_file.empty() ? "(built-in)" : m.ini_file.c_str()).field("period", m.period)
        .field("axes", m.axes).str();
}

std::int64_t program_of(const firtp_lcm::block_t& m) { return m.program; }
std::int64_t program_of(const firtp_lcm::control_t& m) { return m.session; }  // each host counts its own
template <class Message> std::int64_t program_of(const Message&) { return 0; }

// Decodes as Message when the fingerprint matches (decode checks it first); a message whose crc
// does not match is shown, marked, and given no seq key (its fields are not to be trusted).
template <class Message> std::optional<EventText> try_decode(const void* data, int size) {
    const auto received = messages::receive<Message>(data, static_cast<std::size_t>(size));
    if (!received.decoded) return std::nullopt;
    const Message& message = received.message;
    if (received.problem) {  // "corrupted: CRC mismatch (...)" -> " CORRUPTED: CRC mismatch (...)"
        const std::string& problem = *received.problem;
        const std::string why = problem.rfind("corrupted: ", 0) == 0 ? problem.substr(11) : problem;
        return EventText{text(message) + " CORRUPTED: " + why, std::nullopt, true};
    }
    return EventText{text(message), SeqKey{program_of(message), message.seq, std::is_same_v<Message, firtp_lcm::config_t>,
                                           std::is_same_v<Message, firtp_lcm::control_t>}};
}

}  // namespace

EventText describe(const void* data, int size) {
    if (auto e = try_decode<firtp_lcm::block_t>(data, size)) return *e;
    if (auto e = try_decode<firtp_lcm::status_t>(data, size)) return *e;
    if (auto e = try_decode<firtp_lcm::axis_state_t>(data, size)) return *e;
    if (auto e = try_decode<firtp_lcm::control_t>(data, size)) return *e;
    if (auto e = try_decode<firtp_lcm::config_t>(data, size)) return *e;
    return EventText{"? " + std::to_string(size) + " bytes", std::nullopt};
}

}  // namespace firtp::dump
