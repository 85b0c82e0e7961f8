#include "fake_component.hpp"

#include <firtp/messages.hpp>

#include <algorithm>

namespace firtp::host::test {

using firtp_lcm::status_t;

FakeComponent::FakeComponent(lcm::LCM& lcm, int capacity) : lcm_(lcm), capacity_(capacity) {
    block_subscription_ = lcm_.subscribe("FIRTP_BLOCK", &FakeComponent::on_block_bytes, this);
    block_subscription_->setQueueCapacity(0);
    control_subscription_ = lcm_.subscribe("FIRTP_CONTROL", &FakeComponent::on_control_bytes, this);
    control_subscription_->setQueueCapacity(0);
}

FakeComponent::~FakeComponent() {
    lcm_.unsubscribe(block_subscription_);
    lcm_.unsubscribe(control_subscription_);
}

void FakeComponent::fail(std::string text) {
    state = status_t::ERROR;
    error_code_ = status_t::ERROR_LOST_STATE;
    error_text_ = std::move(text);
}

void FakeComponent::refuse_next(std::int32_t code, std::string text) { refusal_.emplace(code, std::move(text)); }

void FakeComponent::preload(std::int64_t other_program, int blocks) {
    program = other_program;
    for (int seq = 1; seq <= blocks; ++seq) {
        firtp_lcm::block_t block{};
        block.program = other_program;
        block.seq = seq;
        queue_.push_back(block);
    }
    next_seq = blocks + 1;
}

// As the bridge: the crc first; a corrupted block is refused as corrupted and not accepted.
void FakeComponent::on_block_bytes(const lcm::ReceiveBuffer* buffer, const std::string&) {
    const auto r = messages::receive<firtp_lcm::block_t>(buffer->data, buffer->data_size);
    if (!r.problem) return on_block(&r.message);
    ++corrupted;
    refuse(status_t::ERROR_CORRUPTED, "block: " + *r.problem);
}

void FakeComponent::on_control_bytes(const lcm::ReceiveBuffer* buffer, const std::string&) {
    const auto r = messages::receive<firtp_lcm::control_t>(buffer->data, buffer->data_size);
    if (!r.problem) return on_control(&r.message);
    ++corrupted;
}

void FakeComponent::on_block(const firtp_lcm::block_t* message) {
    if (drop_once.erase(message->seq) > 0) return;
    if (delay_once.erase(message->seq) > 0) {
        delayed_.push_back(*message);
        return;
    }
    receive(*message);
    if (duplicate_once.erase(message->seq) > 0) receive(*message);
    std::vector<firtp_lcm::block_t> late;
    late.swap(delayed_);
    for (const auto& block : late) receive(block);
}

void FakeComponent::on_control(const firtp_lcm::control_t* message) {
    if (drop_controls > 0) {
        --drop_controls;
        return;
    }
    controls.push_back(*message);
    if (message->seq <= control_seq_) return;  // older than what is in effect
    control_seq_ = message->seq;
    feed_scale_ = message->feed_scale;
    hold_ = message->hold;
    abort_ = message->abort;
}

void FakeComponent::refuse(std::int32_t code, const std::string& text) {
    ++rejected;
    error_code_ = code;
    error_text_ = text;
    if (code == status_t::ERROR_REPEATED) ++repeats;
    if (code == status_t::ERROR_SEQUENCE_GAP) ++gaps;
    if (code == status_t::ERROR_QUEUE_FULL) ++queue_full;
}

void FakeComponent::receive(const firtp_lcm::block_t& message) {
    received.push_back(message.seq);
    if (window_end_ > 0 && message.program == program && message.seq >= window_end_) ++window_violations;
    const std::string seq = "block seq " + std::to_string(message.seq);
    if (state == status_t::ERROR) return refuse(error_code_, error_text_);
    if (abort_) return refuse(status_t::ERROR_NOT_ENABLED, seq + ": aborting");
    if (refusal_) {
        refuse(refusal_->first, refusal_->second);
        refusal_.reset();
        return;
    }
    if (refuse_always && refuse_always->seq == message.seq) return refuse(refuse_always->code, refuse_always->text);
    if (message.program != program) {
        if (!queue_.empty()) return refuse(status_t::ERROR_SEQUENCE_GAP, seq + ": another program is queued");
        if (message.seq != 1) return refuse(status_t::ERROR_SEQUENCE_GAP, seq + ": a new program starts at 1");
        program = message.program;
        next_seq = 1;
    }
    if (message.seq < next_seq) return refuse(status_t::ERROR_REPEATED, seq + ": repeated");
    if (message.seq > next_seq) return refuse(status_t::ERROR_SEQUENCE_GAP, seq + ": expected " + std::to_string(next_seq));
    if (depth() >= capacity_) return refuse(status_t::ERROR_QUEUE_FULL, seq + ": queue full");
    queue_.push_back(message);
    accepted.push_back(message);
    ++next_seq;
    max_depth = std::max(max_depth, depth());
}

void FakeComponent::tick() {
    ++tick_;
    if (state != status_t::ERROR) {
        if (abort_ && !queue_.empty()) {
            queue_.clear();
            ticks_in_block_ = 0;
            state = status_t::ABORTING;
        } else if (queue_.empty()) {
            state = status_t::IDLE;
        } else if (hold_) {
            state = status_t::HOLDING;
        } else {
            state = status_t::MOVING;
            if (++ticks_in_block_ >= ticks_per_block) {
                queue_.pop_front();
                ticks_in_block_ = 0;
                ++executed;
            }
        }
    }
    if (silent) return;
    publish_axis_state();
    publish_status();
}

void FakeComponent::publish_status() {
    status_t status{};
    status.utime = tick_ * 1000;
    status.seq = ++status_seq_;
    status.tick = tick_;
    status.program = program;
    status.next_seq = next_seq;
    status.queue_depth = depth();
    status.queue_free = capacity_ - depth();
    status.current_line = queue_.empty() ? 0 : queue_.front().line;
    status.state = state;
    if (torn_next) status.state = status_t::IDLE, status.queue_depth = 0, torn_next = false;
    status.feed_scale = feed_scale_;
    status.error_code = error_code_;
    status.error_text = error_text_;
    status.rejected = rejected;
    status.corrupted = corrupted;
    window_end_ = status.next_seq + status.queue_free;
    messages::publish(lcm_, "FIRTP_STATUS", status);
}

void FakeComponent::publish_axis_state() {
    firtp_lcm::axis_state_t message{};
    if (++axis_seq_ == skip_axis_seq) ++axis_seq_;
    message.utime = tick_ * 1000;
    message.seq = axis_seq_;
    message.tick = tick_;
    message.time = static_cast<double>(tick_) * 0.001;
    message.line = queue_.empty() ? 0 : queue_.front().line;
    message.position[0] = static_cast<double>(executed);
    messages::publish(lcm_, "FIRTP_AXIS_STATE", message);
    ++axis_published;
}

}  // namespace firtp::host::test
