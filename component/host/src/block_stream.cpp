#include "block_stream.hpp"

#include <algorithm>

namespace firtp::host {

using firtp_lcm::status_t;

BlockStream::BlockStream(std::int64_t program, std::int64_t blocks, StreamSettings settings)
    : program_(program), blocks_(blocks), settings_(settings) {}

void BlockStream::on_status(const status_t& status, Clock::time_point now) {
    const bool ours = status.program == program_;
    if (ours && status.next_seq > acked_) {
        acked_ = std::min(status.next_seq, blocks_ + 1);
        last_progress_ = now;
        go_backs_to_seq_ = 0;
        probing_ = false;
    }
    next_send_ = std::max(next_send_, acked_);

    const std::int64_t free = std::max<std::int32_t>(status.queue_free, 0);
    if (ours)
        limit_ = status.next_seq + free;
    else if (acked_ == 1 && status.queue_depth == 0)  // idle with another program: start ours
        limit_ = 1 + std::min<std::int64_t>(settings_.initial_window, free);
    else  // another program still queued: wait for it
        limit_ = acked_;

    // A gap, a full queue or a corrupted block means blocks from acked_ on were refused (a
    // corrupted one is as good as lost): resend them now, once per seq and resend_timeout (late
    // refusals of the same burst must not restart it again).
    const bool refused_more = have_status_ && status.rejected > last_rejected_;
    const bool resend = status.error_code == status_t::ERROR_SEQUENCE_GAP ||
                        status.error_code == status_t::ERROR_QUEUE_FULL ||
                        status.error_code == status_t::ERROR_CORRUPTED;
    last_rejected_ = status.rejected;
    have_status_ = true;
    if (refused_more && resend && next_send_ > acked_ &&
        (acked_ != go_back_seq_ || now - go_back_time_ >= settings_.resend_timeout))
        go_back(now);
}

void BlockStream::on_time(Clock::time_point now) {
    if (next_send_ > acked_ && now - last_progress_ >= settings_.resend_timeout &&
        now - go_back_time_ >= settings_.resend_timeout)
        go_back(now);
}

std::optional<std::int64_t> BlockStream::next() const {
    std::int64_t limit = have_status_ ? limit_ : 1 + settings_.initial_window;
    if (probing_) limit = std::min(limit, go_back_seq_ + 1);
    if (next_send_ > blocks_ || next_send_ >= limit) return std::nullopt;
    return next_send_;
}

void BlockStream::sent(std::int64_t seq, Clock::time_point now) {
    if (seq == acked_) last_progress_ = now;  // nothing was outstanding: the wait starts now
    next_send_ = seq + 1;
    highest_sent_ = std::max(highest_sent_, seq);
}

void BlockStream::go_back(Clock::time_point now) {
    go_backs_to_seq_ = acked_ == go_back_seq_ ? go_backs_to_seq_ + 1 : 1;
    if (go_backs_to_seq_ > settings_.max_resends) stalled_ = acked_;
    go_back_seq_ = acked_;
    go_back_time_ = now;
    next_send_ = acked_;
    probing_ = true;
    ++go_backs_;
}

}  // namespace firtp::host
