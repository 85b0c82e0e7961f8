#include "record_receiver.hpp"

#include <firtp/messages.hpp>

#include <chrono>
#include <regex>

namespace firtp::cli {
namespace {

constexpr const char* recording_buffer = "recv_buf_size=67108864";  // 64 MiB (the kernel may cap it: net.core.rmem_max)

}  // namespace

std::string recording_url(const std::string& url) {
    std::string full = url;
    if (full.empty()) {
        const char* from_environment = std::getenv("LCM_DEFAULT_URL");
        full = from_environment != nullptr && *from_environment != '\0'
                   ? from_environment
                   : std::regex_replace(messages::default_url(), std::regex("recv_buf_size=[0-9]+"), recording_buffer);
    }
    if (full.rfind("udpm://", 0) != 0 || full.find("recv_buf_size=") != std::string::npos) return full;
    return full + (full.find('?') == std::string::npos ? "?" : "&") + recording_buffer;
}

RecordReceiver::RecordReceiver(const std::string& url, const std::string& channels) : lcm_(messages::open(url)) {
    subscription_ = lcm_->subscribe(channels, &RecordReceiver::on_message, this);
    messages::keep_everything(subscription_);
    thread_ = std::thread([this] { receive_loop(); });
}

RecordReceiver::~RecordReceiver() {
    stop();
    lcm_->unsubscribe(subscription_);
}

void RecordReceiver::stop() {
    stopping_ = true;
    if (thread_.joinable()) thread_.join();
}

void RecordReceiver::receive_loop() {
    while (!stopping_) lcm_->handleTimeout(50);
}

// Runs in the receive thread: a copy, nothing else.
void RecordReceiver::on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    ReceivedEvent event;
    event.channel = channel;
    event.utime = buffer->recv_utime;
    const auto* bytes = static_cast<const std::uint8_t*>(buffer->data);
    event.data.assign(bytes, bytes + buffer->data_size);
    {
        const std::lock_guard lock(mutex_);
        pending_.push_back(std::move(event));
    }
    arrived_.notify_one();
}

void RecordReceiver::take(std::vector<ReceivedEvent>& out, int timeout_ms) {
    std::unique_lock lock(mutex_);
    arrived_.wait_for(lock, std::chrono::milliseconds(timeout_ms), [this] { return !pending_.empty(); });
    if (out.empty()) {
        out.swap(pending_);
    } else {
        for (ReceivedEvent& e : pending_) out.push_back(std::move(e));
        pending_.clear();
    }
}

}  // namespace firtp::cli
