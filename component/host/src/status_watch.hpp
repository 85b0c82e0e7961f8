// Judges each status_t (in arrival order) for the outcome of one program: done, failed, aborted.
#pragma once

#include <firtp/host.hpp>

#include <cstdint>
#include <string>

namespace firtp::host {

class StatusWatch {
public:
    StatusWatch(std::int64_t program, std::int64_t blocks) : program_(program), blocks_(blocks) {}

    // running, or the final result this status shows. abort_requested: the host asked for an
    // abort before this status arrived.
    Result on_status(const firtp_lcm::status_t& status, bool abort_requested);
    const std::string& error() const { return error_; }

private:
    Result fail(std::string text);

    std::int64_t program_;
    std::int64_t blocks_;
    bool have_previous_ = false;
    std::int64_t previous_rejected_ = 0;
    std::int32_t previous_code_ = 0;
    std::string previous_text_;
    std::string error_;
};

}  // namespace firtp::host
