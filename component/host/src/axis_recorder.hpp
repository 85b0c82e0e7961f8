// FIRTP_AXIS_STATE bookkeeping: counts messages and seq gaps, optionally keeps every message.
#pragma once

#include <firtp_lcm/axis_state_t.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace firtp::host {

class AxisRecorder {
public:
    explicit AxisRecorder(bool keep) : keep_(keep) {}

    void on_message(const firtp_lcm::axis_state_t& message);

    std::int64_t received() const { return received_; }
    std::int64_t lost() const { return lost_; }                // seqs skipped
    std::int64_t out_of_order() const { return out_of_order_; } // seq not above the previous one
    // "" when complete, else e.g. "12 axis-state messages lost (first after seq 40)".
    std::string gap_text() const;
    const std::vector<firtp_lcm::axis_state_t>& messages() const { return messages_; }

private:
    bool keep_;
    std::int64_t received_ = 0;
    std::int64_t last_seq_ = 0;
    std::int64_t lost_ = 0;
    std::int64_t out_of_order_ = 0;
    std::int64_t first_gap_after_ = 0;
    std::vector<firtp_lcm::axis_state_t> messages_;
};

}  // namespace firtp::host
