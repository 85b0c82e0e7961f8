#include <firtp/lcm_recorder.hpp>

#include <firtp/messages.hpp>

#include <stdexcept>

namespace firtp {

LcmRecorder::LcmRecorder(lcm::LCM& lcm, const std::filesystem::path& file, const std::string& channels)
    : lcm_(&lcm), log_(std::make_unique<lcm::LogFile>(file.string(), "w")) {
    if (!log_->good()) throw std::runtime_error("cannot write the LCM log '" + file.string() + "'");
    subscription_ = lcm.subscribe(channels, &LcmRecorder::on_message, this);
    messages::keep_everything(subscription_);
}

LcmRecorder::~LcmRecorder() { lcm_->unsubscribe(subscription_); }

void LcmRecorder::on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    lcm::LogEvent event;
    event.eventnum = events_++;
    event.timestamp = buffer->recv_utime;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(buffer->data_size);
    event.data = buffer->data;
    log_->writeEvent(&event);
}

}  // namespace firtp
