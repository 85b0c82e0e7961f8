// The LinuxCNC motion side of firtp-lcm-bridge (mode `motion`, e.g. with firtp_tp as TPMOD):
// LinuxCNC's `sampler` copies the planner's output (axis.L.pos-cmd) and motion.program-line into
// its hal_stream every servo period on the real-time side; this drains that stream and publishes
// every period as FIRTP_AXIS_STATE (and every Nth as FIRTP_AXIS_STATE_LIVE), and the motion
// status as FIRTP_STATUS. Nothing is dropped silently: the stream's overrun count (and sample
// numbers) show every period the sampler could not write (a full stream); they are skipped in the
// ticks, reported as ERROR_LOST_STATE with their count and on the pin `lost`.
#pragma once

#include <firtp/defaults.hpp>
#include <firtp/messages.hpp>
#include <firtp/types.hpp>

#include <array>
#include <cstdint>
#include <string>

namespace firtp {

struct MotionOptions {
    std::string name = "firtp-lcm-bridge";  // HAL component name and pin prefix
    int axes = 3;                           // sampler columns 0..axes-1: positions (X Y Z ...)
    double period = defaults::servo_period;  // servo period, s
    int sampler_channel = 0;                // `loadrt sampler` channel N (its hal_stream)
    int live_decimation = messages::default_live_decimation;  // FIRTP_AXIS_STATE_LIVE every N periods (0: never)
    int status_every = messages::default_status_every;        // FIRTP_STATUS every N periods, and on every change
};

// The sampler channel's layout: the axes' positions (float), then the program line (s32).
std::string motion_sampler_cfg(int axes);

class MotionPublisher {
public:
    // Registers the HAL component with its pins and attaches to the sampler's stream; throws
    // std::runtime_error saying what is wrong (no such channel, a different layout).
    MotionPublisher(lcm::LCM& lcm, const MotionOptions& options);
    ~MotionPublisher();
    MotionPublisher(const MotionPublisher&) = delete;
    MotionPublisher& operator=(const MotionPublisher&) = delete;

    // Non-blocking: publishes every sample in the stream, then the status when due.
    void poll();

    std::int64_t states_published() const { return states_; }
    std::int64_t states_lost() const { return lost_; }

private:
    struct Pins;
    void publish_state(std::int64_t tick, std::int32_t line, const double* position);
    void publish_status();
    std::int8_t motion_state() const;
    void lose(std::int64_t periods);

    lcm::LCM* lcm_;
    MotionOptions options_;
    int comp_id_ = -1;
    Pins* pins_ = nullptr;
    struct Stream;
    Stream* stream_ = nullptr;
    std::int64_t last_tick_ = -1;     // servo period of the newest record published
    std::uint32_t last_sample_ = 0;   // its sample number in the stream
    std::int64_t overruns_seen_ = 0;  // the stream's overrun count already accounted for
    std::array<double, max_axes> previous_position_{}, previous_velocity_{};
    int history_ = 0;                 // consecutive samples behind the current one (0, 1, 2)
    std::int64_t lost_ = 0;
    std::int64_t states_ = 0, state_seq_ = 0, status_seq_ = 0;
    std::int32_t line_ = 0;
    std::int8_t last_state_ = -1;
    std::int64_t periods_since_status_ = 0;
    bool status_due_ = true;
};

}  // namespace firtp
