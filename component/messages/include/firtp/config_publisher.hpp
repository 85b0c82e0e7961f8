// FIRTP_CONFIG out: the machine and settings of a running component, now and then every second,
// so that a recorder started later still logs them (`firtp serve`, `firtp run`, firtp-lcm-bridge).
#pragma once

#include <firtp_lcm/config_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <chrono>

namespace firtp::messages {

class ConfigPublisher {
public:
    // Publishes `message` now, seq 1, and then every `every` with the next seq.
    ConfigPublisher(lcm::LCM& lcm, firtp_lcm::config_t message,
                    std::chrono::milliseconds every = std::chrono::milliseconds(1000));
    void poll();  // publishes when due

private:
    void publish();
    lcm::LCM* lcm_;
    firtp_lcm::config_t message_;
    std::chrono::milliseconds every_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace firtp::messages
