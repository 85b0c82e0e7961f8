#include "axis_recorder.hpp"

namespace firtp::host {

void AxisRecorder::on_message(const firtp_lcm::axis_state_t& message) {
    if (received_ > 0 && message.seq != last_seq_ + 1) {
        if (lost_ == 0 && out_of_order_ == 0) first_gap_after_ = last_seq_;
        if (message.seq > last_seq_)
            lost_ += message.seq - last_seq_ - 1;
        else
            ++out_of_order_;
    }
    ++received_;
    last_seq_ = message.seq;
    if (keep_) messages_.push_back(message);
}

std::string AxisRecorder::gap_text() const {
    if (lost_ == 0 && out_of_order_ == 0) return "";
    std::string text = std::to_string(lost_) + " axis-state messages lost";
    if (out_of_order_ > 0) text += ", " + std::to_string(out_of_order_) + " out of order";
    return text + " (first after seq " + std::to_string(first_gap_after_) + ")";
}

}  // namespace firtp::host
