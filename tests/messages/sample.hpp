// Valid blocks and messages for the message tests, and a per-test temporary file name.
#pragma once

#include <firtp/messages.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace firtp::messages::test {

inline Block sample_block() {
    Block block;
    for (int axis = 0; axis < max_axes; ++axis) block.target[axis] = 1.5 * (axis + 1) - 4.0;
    block.feed = 25.0;
    block.termination = Termination::blend;
    block.tolerance = 0.02;
    block.type = MotionType::feed;
    block.line = 40;
    return block;
}

inline firtp_lcm::block_t sample_message(std::int64_t seq = 12) { return to_message(sample_block(), 7, seq, 1000); }

inline firtp_lcm::status_t sample_status() {
    firtp_lcm::status_t status{};
    status.utime = 11;
    status.seq = 3;
    status.tick = 4000;
    status.program = 7;
    status.next_seq = 13;
    status.queue_depth = 5;
    status.queue_free = 59;
    status.current_line = 38;
    status.state = firtp_lcm::status_t::HOLDING;
    status.feed_scale = 0.5;
    status.error_code = firtp_lcm::status_t::ERROR_SEQUENCE_GAP;
    status.error_text = "block seq 15: sequence gap";
    status.rejected = 2;
    return status;
}

inline firtp_lcm::axis_state_t sample_axis_state() {
    firtp_lcm::axis_state_t state{};
    state.utime = 12;
    state.seq = 99;
    state.tick = 4001;
    state.time = 4.001;
    state.line = 38;
    for (int axis = 0; axis < max_axes; ++axis) {
        state.position[axis] = axis + 0.25;
        state.velocity[axis] = -axis * 1.5;
        state.acceleration[axis] = axis * 100.0;
    }
    state.program = 7;
    state.next_seq = 12;
    return state;
}

// Whether `part` occurs in `text`.
inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline firtp_lcm::control_t sample_control() {
    firtp_lcm::control_t c{};
    c.utime = 123456789;
    c.session = 1000;
    c.seq = 42;
    c.feed_scale = 0.75;
    c.hold = 1;
    c.abort = 0;
    return c;
}

// A file name unique to this test and process, removed when the object goes.
class TempFile {
public:
    explicit TempFile(const std::string& suffix) {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                (std::string("firtp-msg-") + info->test_suite_name() + "-" + info->name() + "-" +
                 std::to_string(::getpid()) + suffix);
    }
    ~TempFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    std::string string() const { return path_.string(); }

private:
    std::filesystem::path path_;
};

}  // namespace firtp::messages::test
