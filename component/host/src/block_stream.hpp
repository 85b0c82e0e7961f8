// Which block to send next: flow control (seq < next_seq + queue_free) and go-back-N resending.
// Pure bookkeeping, no LCM: fed with statuses and the time, asked for the next seq.
// After a go-back the first unaccepted block goes out alone until it is accepted: the
// component's error_code is only the latest error, so a block refused for a real reason would
// otherwise be hidden behind the gap errors of the blocks sent after it.
#pragma once

#include <firtp/host.hpp>

#include <cstdint>
#include <optional>

namespace firtp::host {

struct StreamSettings {
    int initial_window = 16;                 // before the first status
    Clock::duration resend_timeout{};        // no progress for this long -> go back
    int max_resends = 10;                    // go-backs to one seq before it counts as stalled
};

class BlockStream {
public:
    BlockStream(std::int64_t program, std::int64_t blocks, StreamSettings settings);

    void on_status(const firtp_lcm::status_t& status, Clock::time_point now);
    void on_time(Clock::time_point now);  // go back when nothing was acknowledged for a while

    std::optional<std::int64_t> next() const;        // seq flow control allows now
    void sent(std::int64_t seq, Clock::time_point now);  // after publishing next()

    std::int64_t acknowledged() const { return acked_ - 1; }
    std::int64_t highest_sent() const { return highest_sent_; }
    std::int64_t go_backs() const { return go_backs_; }
    // The seq resent more than max_resends times without being accepted, if any.
    std::optional<std::int64_t> stalled() const { return stalled_; }

private:
    void go_back(Clock::time_point now);

    std::int64_t program_;
    std::int64_t blocks_;
    StreamSettings settings_;
    bool have_status_ = false;
    std::int64_t limit_ = 1;         // first seq flow control does not allow yet
    std::int64_t acked_ = 1;         // lowest seq not yet accepted (status next_seq)
    std::int64_t next_send_ = 1;
    std::int64_t highest_sent_ = 0;
    std::int64_t last_rejected_ = 0;
    Clock::time_point last_progress_{};
    std::int64_t go_back_seq_ = 0;   // seq of the latest go-back
    Clock::time_point go_back_time_{};
    int go_backs_to_seq_ = 0;        // go-backs to go_back_seq_ without progress
    bool probing_ = false;           // after a go-back only go_back_seq_ goes out until accepted
    std::int64_t go_backs_ = 0;
    std::optional<std::int64_t> stalled_;
};

}  // namespace firtp::host
