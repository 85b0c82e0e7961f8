#include "status_watch.hpp"

#include <utility>

namespace firtp::host {
namespace {

using firtp_lcm::status_t;

// Errors go-back-N repairs (or that are harmless); anything else ends the program.
bool recoverable(std::int32_t code) {
    return code == status_t::ERROR_NONE || code == status_t::ERROR_SEQUENCE_GAP ||
           code == status_t::ERROR_REPEATED || code == status_t::ERROR_QUEUE_FULL ||
           code == status_t::ERROR_CORRUPTED;  // refused as if lost: the resend repairs it
}

std::string error_text(const status_t& status) {
    if (!status.error_text.empty()) return status.error_text;
    return "component error code " + std::to_string(status.error_code);
}

}  // namespace

Result StatusWatch::on_status(const status_t& status, bool abort_requested) {
    // error_code is the latest error, possibly from an earlier program: only a change (or a new
    // refusal) after the first status seen counts.
    const bool news = have_previous_ &&
                      (status.rejected > previous_rejected_ || status.error_code != previous_code_ ||
                       status.error_text != previous_text_);
    have_previous_ = true;
    previous_rejected_ = status.rejected;
    previous_code_ = status.error_code;
    previous_text_ = status.error_text;

    if (status.state == status_t::ERROR)
        return fail(status.error_code == status_t::ERROR_NONE ? "component is in the error state"
                                                              : error_text(status));
    const bool ours = status.program == program_;
    bool idle_and_empty = status.state == status_t::IDLE && status.queue_depth == 0;
    if (!idle_and_empty) {
        settled_tick_ = -1;
    } else if (settled_tick_ < 0 || status.tick <= settled_tick_) {
        if (settled_tick_ < 0) settled_tick_ = status.tick;
        idle_and_empty = false;  // not yet: seen in one period only
    }
    if (abort_requested) return idle_and_empty ? Result::aborted : Result::running;
    if (news && !recoverable(status.error_code)) return fail(error_text(status));
    if (ours && status.state == status_t::DISABLED)
        return fail("component was disabled before the program finished");
    if (ours && status.next_seq == blocks_ + 1 && idle_and_empty) return Result::done;
    return Result::running;
}

Result StatusWatch::fail(std::string text) {
    error_ = std::move(text);
    return Result::failed;
}

}  // namespace firtp::host
