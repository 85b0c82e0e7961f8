// The receive side of `firtp record`: its own thread does nothing but let LCM deliver and copy each
// message into memory (unbounded subscription queue, large socket buffer), so that a slow disk
// or a burst never makes LCM drop a message; the caller takes the events in batches and writes them.
#pragma once

#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace firtp::cli {

struct ReceivedEvent {
    std::string channel;
    std::int64_t utime = 0;  // when LCM received it
    std::vector<std::uint8_t> data;
};

class RecordReceiver {
public:
    // Opens `url` (messages::open) and starts receiving `channels` (a regular expression).
    // Throws std::runtime_error when LCM cannot start.
    RecordReceiver(const std::string& url, const std::string& channels);
    ~RecordReceiver();
    RecordReceiver(const RecordReceiver&) = delete;
    RecordReceiver& operator=(const RecordReceiver&) = delete;

    // Waits up to `timeout_ms` for events, then appends every event received so far to `out`.
    void take(std::vector<ReceivedEvent>& out, int timeout_ms);
    // Stops receiving; events already received can still be taken.
    void stop();

private:
    void receive_loop();
    void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel);

    std::unique_ptr<lcm::LCM> lcm_;
    lcm::Subscription* subscription_ = nullptr;
    std::mutex mutex_;
    std::condition_variable arrived_;
    std::vector<ReceivedEvent> pending_;
    std::atomic<bool> stopping_{false};
    std::thread thread_;
};

// udpm:// URL for recording: `url` (or LCM's default group) with a 64 MiB socket receive buffer
// unless the URL names its own recv_buf_size. Other providers unchanged.
std::string recording_url(const std::string& url);

}  // namespace firtp::cli
