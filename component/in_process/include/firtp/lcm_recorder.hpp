// Records every message on an LCM object into an LCM log file (what lcm-logger does, in process,
// so memq:// traffic can be recorded too).
#pragma once

#include <lcm/lcm-cpp.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace firtp {

class LcmRecorder {
public:
    // Throws std::runtime_error naming the file when it cannot be opened.
    LcmRecorder(lcm::LCM& lcm, const std::filesystem::path& file, const std::string& channels = ".*");
    ~LcmRecorder();
    LcmRecorder(const LcmRecorder&) = delete;
    LcmRecorder& operator=(const LcmRecorder&) = delete;

    std::int64_t events() const { return events_; }

private:
    void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel);

    lcm::LCM* lcm_;
    std::unique_ptr<lcm::LogFile> log_;
    lcm::Subscription* subscription_ = nullptr;
    std::int64_t events_ = 0;
};

}  // namespace firtp
