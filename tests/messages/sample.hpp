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
