// Operator control levels (feed override, hold, abort) as control_t messages: a new message after
// every change and again every period, so a lost one is repaired.
#pragma once

#include <firtp/host.hpp>
#include <firtp_lcm/control_t.hpp>

#include <cstdint>
#include <optional>

namespace firtp::host {

class ControlSender {
public:
    ControlSender(std::int64_t session, double feed_scale, double max_feed_scale, Clock::duration period);

    void set_feed_scale(double scale);  // clamped to 0 .. max (NaN ignored)
    void set_hold(bool on);
    void set_abort(bool on);

    // The message to publish now (first call, after a change, or the period elapsed), else none.
    std::optional<firtp_lcm::control_t> due(Clock::time_point now, std::int64_t utime);

    double feed_scale() const { return feed_scale_; }
    double max_feed_scale() const { return max_feed_scale_; }
    bool hold() const { return hold_; }
    bool abort() const { return abort_; }

private:
    std::int64_t session_;
    double feed_scale_;
    double max_feed_scale_;
    Clock::duration period_;
    bool hold_ = false;
    bool abort_ = false;
    bool changed_ = true;  // publish the levels at start
    std::int64_t seq_ = 0;
    Clock::time_point last_{};
};

}  // namespace firtp::host
