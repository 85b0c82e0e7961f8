// Every check a block message passes before it may reach the planner.
#include <firtp/messages.hpp>

#include <charconv>
#include <cmath>
#include <vector>

namespace firtp::messages {
namespace {

constexpr double max_coordinate = 1e6;  // units; beyond this a target is a corrupt or unit-confused value

// "NaN", "inf", "-inf", or the number.
std::string text(double value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;  // shortest exact form
    return std::string(buffer, end);
}

void check_target(const firtp_lcm::block_t& message, std::vector<std::string>& problems) {
    for (int axis = 0; axis < max_axes; ++axis) {
        const double value = message.target[axis];
        const std::string name = std::string("target ") + axis_letters[axis];
        if (!std::isfinite(value))
            problems.push_back(name + " is " + text(value));
        else if (std::abs(value) > max_coordinate)
            problems.push_back(name + " is " + text(value) + ", beyond +-1e6");
    }
}

void check_feed(double feed, std::vector<std::string>& problems) {
    if (!std::isfinite(feed) || feed <= 0.0) problems.push_back("feed is " + text(feed) + " (must be finite and > 0)");
}

void check_tolerance(double tolerance, std::vector<std::string>& problems) {
    if (!(tolerance > 0.0)) problems.push_back("tolerance is " + text(tolerance) + " (must be > 0 or inf)");
}

void check_kinds(const firtp_lcm::block_t& message, std::vector<std::string>& problems) {
    const int type = message.motion_type;
    if (type != static_cast<int>(MotionType::traverse) && type != static_cast<int>(MotionType::feed))
        problems.push_back("unknown motion_type " + std::to_string(type) + " (1 traverse, 2 feed)");
    const int termination = message.termination;
    if (termination != static_cast<int>(Termination::exact_stop) && termination != static_cast<int>(Termination::blend))
        problems.push_back("unknown termination " + std::to_string(termination) + " (0 exact stop, 1 blend)");
}

}  // namespace

std::string describe(const firtp_lcm::block_t& message) {
    return "block seq " + std::to_string(message.seq) + " (line " + std::to_string(message.line) + ")";
}

std::optional<std::string> validate(const firtp_lcm::block_t& message) {
    std::vector<std::string> problems;
    if (message.seq < 1) problems.push_back("seq must be >= 1");
    check_target(message, problems);
    check_feed(message.feed, problems);
    check_tolerance(message.tolerance, problems);
    check_kinds(message, problems);
    if (problems.empty()) return std::nullopt;

    std::string out = describe(message) + ": ";
    for (std::size_t i = 0; i < problems.size(); ++i) out += (i == 0 ? "" : "; ") + problems[i];
    return out;
}

}  // namespace firtp::messages
