#include <firtp/config_publisher.hpp>

#include <firtp/messages.hpp>

namespace firtp::messages {

ConfigPublisher::ConfigPublisher(lcm::LCM& lcm, firtp_lcm::config_t message, std::chrono::milliseconds every)
    : lcm_(&lcm), message_(std::move(message)), every_(every) {
    publish();
}

void ConfigPublisher::poll() {
    if (std::chrono::steady_clock::now() - last_ >= every_) publish();
}

void ConfigPublisher::publish() {
    ++message_.seq;
    message_.utime = now_utime();
    messages::publish(*lcm_, config_channel, message_);
    last_ = std::chrono::steady_clock::now();
}

}  // namespace firtp::messages
