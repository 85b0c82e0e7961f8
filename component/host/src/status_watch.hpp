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
    // The tick of the first status in a row that showed the component idle with nothing queued
    // (-1: none): an end is taken from the next one, of a later period. A bridge reads the
    // component's pins one by one: between two of them the component may take the last blocks
    // from its stream and not yet say so, and one status reads idle and empty with every block
    // sent (firtp_config_host_diamond ended LinuxCNC after 0.2 s of 0.8). firtp-lcm-bridge now
    // counts those blocks itself (Bridge::component_depth, from its axis-state stream); this
    // stays for a status that cannot (no axis-state stream, a bridge of an older build).
    std::int64_t settled_tick_ = -1;
};

}  // namespace firtp::host
