// Block <-> block_t. No checks here: validate() decides whether a message may become a block.
#include <firtp/messages.hpp>

#include <algorithm>
#include <chrono>
#include <limits>

namespace firtp::messages {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

std::int32_t clamp_line(std::int64_t line) {
    using limits = std::numeric_limits<std::int32_t>;
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(line, limits::min(), limits::max()));
}

}  // namespace

std::int64_t now_utime() {
    using namespace std::chrono;
    return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

firtp_lcm::block_t to_message(const Block& block, std::int64_t program, std::int64_t seq, std::int64_t utime) {
    firtp_lcm::block_t message{};
    message.utime = utime;
    message.program = program;
    message.seq = seq;
    message.line = clamp_line(block.line);
    message.motion_type = static_cast<std::int8_t>(block.type);
    message.termination = static_cast<std::int8_t>(block.termination);
    for (int axis = 0; axis < max_axes; ++axis) message.target[axis] = block.target[axis];
    message.feed = block.feed;
    // The G-code reader gives exact stops tolerance 0 ("none"); on the wire that is +inf, since a
    // message's tolerance must be > 0. An exact stop does not use it.
    const bool exact_stop_without = block.termination == Termination::exact_stop && block.tolerance == 0.0;
    message.tolerance = exact_stop_without ? infinity : block.tolerance;
    return message;
}

Block to_block(const firtp_lcm::block_t& message) {
    Block block;
    for (int axis = 0; axis < max_axes; ++axis) block.target[axis] = message.target[axis];
    block.feed = message.feed;
    block.termination = static_cast<Termination>(message.termination);
    block.tolerance = message.tolerance;
    block.type = static_cast<MotionType>(message.motion_type);
    block.line = message.line;
    return block;
}

}  // namespace firtp::messages
