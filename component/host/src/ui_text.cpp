// The text side of the operator interface: keys, command lines, the progress line.
#include <firtp/host_ui.hpp>

#include <firtp/program_event.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace firtp::host {
namespace {

std::string_view trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

int percent(std::size_t part, std::size_t whole) {
    return whole == 0 ? 100 : static_cast<int>(part * 100 / whole);
}

}  // namespace

std::string event_text(const firtp_lcm::event_t& event) {
    const auto kind = static_cast<EventKind>(event.kind);
    std::string text = "line " + std::to_string(event.line) + ": " + std::string(event_name(kind));
    char value[48] = "";
    switch (kind) {
        case EventKind::spindle_speed: std::snprintf(value, sizeof value, " S%g", event.value); break;
        case EventKind::tool_select:
        case EventKind::tool_change: std::snprintf(value, sizeof value, " T%g", event.value); break;
        case EventKind::dwell: std::snprintf(value, sizeof value, " %g s", event.value); break;
        default: break;
    }
    return text + value + " reached";
}

std::optional<UiCommand> command_for_key(char key) {
    using Kind = UiCommand::Kind;
    switch (key) {
        case '+':
        case '=': return UiCommand{Kind::feed_up};
        case '-': return UiCommand{Kind::feed_down};
        case ' ': return UiCommand{Kind::toggle_hold};
        case 'a': return UiCommand{Kind::abort};
        case 'q': return UiCommand{Kind::quit};
    }
    return std::nullopt;
}

std::optional<UiCommand> parse_command_line(std::string_view line, std::string& error) {
    using Kind = UiCommand::Kind;
    error.clear();
    line = trim(line);
    if (line.empty() || line.front() == '#') return std::nullopt;
    const auto space = line.find_first_of(" \t");
    const std::string_view word = line.substr(0, space);
    const std::string_view argument = space == std::string_view::npos ? "" : trim(line.substr(space));
    if (word == "feed") {
        double value = 0.0;
        const auto [end, ec] = std::from_chars(argument.data(), argument.data() + argument.size(), value);
        if (argument.empty() || ec != std::errc() || end != argument.data() + argument.size() ||
            !std::isfinite(value) || value < 0.0) {
            error = "feed needs a number >= 0, e.g. 'feed 0.8'";
            return std::nullopt;
        }
        return UiCommand{Kind::set_feed, value};
    }
    std::optional<UiCommand> command;
    if (word == "hold") command = UiCommand{Kind::hold};
    if (word == "resume") command = UiCommand{Kind::resume};
    if (word == "abort") command = UiCommand{Kind::abort};
    if (word == "quit") command = UiCommand{Kind::quit};
    // (append, not "'" + string: GCC 12 gives a false -Wrestrict warning on that in Release)
    if (!command)
        error.append("unknown command '").append(word).append("' (feed N, hold, resume, abort, quit)");
    else if (!argument.empty())
        error.append("'").append(word).append("' takes no argument");
    return error.empty() ? command : std::nullopt;
}

double stepped_feed(double current, int steps, double max_feed) {
    const double grid = std::round(current * 10.0) + steps;
    return std::clamp(grid / 10.0, 0.0, std::max(max_feed, 0.0));
}

std::string progress_text(const Progress& p) {
    char text[200];
    std::snprintf(text, sizeof text, "acknowledged %d%%, executed %d%% (%zu/%zu blocks), line %d, %s, feed %.0f%%",
                  percent(p.acknowledged, p.blocks), percent(p.executed, p.blocks), p.executed, p.blocks,
                  p.line, state_name(p.state), p.feed_in_effect * 100.0);
    std::string result = text;
    if (std::abs(p.feed_request - p.feed_in_effect) > 1e-9) {
        std::snprintf(text, sizeof text, " (asked %.0f%%)", p.feed_request * 100.0);
        result += text;
    }
    if (p.abort)
        result += ", abort requested";
    else if (p.hold)
        result += ", hold requested";
    return result;
}

}  // namespace firtp::host
