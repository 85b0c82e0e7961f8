#include "control_sender.hpp"

#include <algorithm>
#include <cmath>

namespace firtp::host {

ControlSender::ControlSender(std::int64_t session, double feed_scale, double max_feed_scale, Clock::duration period)
    : session_(session), feed_scale_(0.0), max_feed_scale_(std::max(max_feed_scale, 0.0)), period_(period) {
    set_feed_scale(feed_scale);
    changed_ = true;
}

void ControlSender::set_feed_scale(double scale) {
    if (std::isnan(scale)) return;
    const double clamped = std::clamp(scale, 0.0, max_feed_scale_);
    changed_ = changed_ || clamped != feed_scale_;
    feed_scale_ = clamped;
}

void ControlSender::set_hold(bool on) {
    changed_ = changed_ || on != hold_;
    hold_ = on;
}

void ControlSender::set_abort(bool on) {
    changed_ = changed_ || on != abort_;
    abort_ = on;
}

std::optional<firtp_lcm::control_t> ControlSender::due(Clock::time_point now, std::int64_t utime) {
    if (!changed_ && now - last_ < period_) return std::nullopt;
    changed_ = false;
    last_ = now;
    firtp_lcm::control_t message{};
    message.utime = utime;
    message.session = session_;
    message.seq = ++seq_;
    message.feed_scale = feed_scale_;
    message.hold = hold_;
    message.abort = abort_;
    return message;
}

}  // namespace firtp::host
