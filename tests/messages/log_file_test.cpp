// lcm::LogFile round trips of each type, and what decode does with broken bytes.
#include "sample.hpp"

#include <cstring>
#include <limits>
#include <vector>

namespace firtp::messages {
namespace {

using test::sample_axis_state;
using test::sample_status;

template <class Message> std::vector<unsigned char> encode(const Message& message) {
    std::vector<unsigned char> bytes(static_cast<std::size_t>(message.getEncodedSize()));
    EXPECT_EQ(message.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
    return bytes;
}

void write_event(lcm::LogFile& log, const std::string& channel, std::int64_t timestamp,
                 std::vector<unsigned char>& bytes) {
    lcm::LogEvent event{};
    event.timestamp = timestamp;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    ASSERT_EQ(log.writeEvent(&event), 0);
}



firtp_lcm::control_t logged_control() {
    firtp_lcm::control_t control{};
    control.utime = 13;
    control.seq = 2;
    control.feed_scale = 1.2;
    control.hold = true;
    control.abort = false;
    return control;
}

template <class Message> Message read_as(const lcm::LogEvent& event) {
    Message message{};
    EXPECT_EQ(message.decode(event.data, 0, event.datalen), event.datalen);
    return message;
}

TEST(LogFile, EachTypeRoundTrips) {
    const test::TempFile file(".lcmlog");
    const auto block = test::sample_message(12);
    const auto status = sample_status();
    const auto axis_state = sample_axis_state();
    const auto control = logged_control();
    {
        lcm::LogFile log(file.string(), "w");
        ASSERT_TRUE(log.good());
        auto b = encode(block), s = encode(status), a = encode(axis_state), c = encode(control);
        write_event(log, block_channel, 100, b);
        write_event(log, status_channel, 200, s);
        write_event(log, axis_state_channel, 300, a);
        write_event(log, control_channel, 400, c);
    }
    lcm::LogFile log(file.string(), "r");
    ASSERT_TRUE(log.good());

    const lcm::LogEvent* event = log.readNextEvent();
    ASSERT_NE(event, nullptr);
    EXPECT_EQ(event->channel, block_channel);
    EXPECT_EQ(event->timestamp, 100);
    const auto block_back = read_as<firtp_lcm::block_t>(*event);
    EXPECT_EQ(validate(block_back), std::nullopt);
    EXPECT_EQ(to_block(block_back).target, test::sample_block().target);
    EXPECT_EQ(block_back.seq, 12);
    EXPECT_EQ(block_back.program, 7);

    ASSERT_NE(event = log.readNextEvent(), nullptr);
    EXPECT_EQ(event->channel, status_channel);
    const auto status_back = read_as<firtp_lcm::status_t>(*event);
    EXPECT_EQ(status_back.next_seq, 13);
    EXPECT_EQ(status_back.queue_free, 59);
    EXPECT_EQ(status_back.state, firtp_lcm::status_t::HOLDING);
    EXPECT_EQ(status_back.error_text, status.error_text);
    EXPECT_EQ(status_back.rejected, 2);

    ASSERT_NE(event = log.readNextEvent(), nullptr);
    EXPECT_EQ(event->channel, axis_state_channel);
    const auto axis_back = read_as<firtp_lcm::axis_state_t>(*event);
    EXPECT_EQ(axis_back.tick, 4001);
    EXPECT_EQ(std::memcmp(axis_back.position, axis_state.position, sizeof axis_state.position), 0);
    EXPECT_EQ(std::memcmp(axis_back.acceleration, axis_state.acceleration, sizeof axis_state.acceleration), 0);

    ASSERT_NE(event = log.readNextEvent(), nullptr);
    EXPECT_EQ(event->channel, control_channel);
    const auto control_back = read_as<firtp_lcm::control_t>(*event);
    EXPECT_EQ(control_back.feed_scale, 1.2);
    EXPECT_TRUE(control_back.hold);
    EXPECT_FALSE(control_back.abort);

    EXPECT_EQ(log.readNextEvent(), nullptr);
}

TEST(Decode, TruncatedBufferFails) {
    const auto bytes = encode(test::sample_message());
    for (std::size_t length = 0; length < bytes.size(); ++length) {
        firtp_lcm::block_t message;
        EXPECT_LT(message.decode(bytes.data(), 0, static_cast<int>(length)), 0) << length;
    }
    const auto status = encode(sample_status());
    for (std::size_t length = 0; length < status.size(); ++length) {
        firtp_lcm::status_t message;
        EXPECT_LT(message.decode(status.data(), 0, static_cast<int>(length)), 0) << length;
    }
}

TEST(Decode, WrongTypeFails) {
    const auto bytes = encode(sample_status());
    firtp_lcm::block_t message;
    EXPECT_LT(message.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
}

// lcm-gen 1.3.1 checks a string's length against the buffer but not against 1: with a length of
// 0 or less, status_t::decode threw std::length_error or (INT32_MIN) copied 2 GiB from past the
// buffer (found by tests/fuzz/fuzz_lcm). lcm-types/fix_string_decode.cmake makes it refuse them.
TEST(Decode, StringLengthBelowOneIsRefused) {
    const auto good = encode(sample_status());
    constexpr std::size_t length_at = 8 + 5 * 8 + 3 * 4 + 1 + 8 + 4;  // hash, then the fields before error_text
    ASSERT_EQ(good[length_at + 3], sample_status().error_text.size() + 1);  // big-endian, with its \0
    for (std::int32_t length : {0, -1, -1000, std::numeric_limits<std::int32_t>::min()}) {
        auto bytes = good;
        for (int i = 0; i < 4; ++i)
            bytes[length_at + i] = static_cast<unsigned char>(static_cast<std::uint32_t>(length) >> (24 - 8 * i));
        firtp_lcm::status_t status;
        EXPECT_LT(status.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0) << length;
    }
    auto empty = good;  // length 1: the empty string
    for (int i = 0; i < 4; ++i) empty[length_at + i] = i == 3 ? 1 : 0;
    firtp_lcm::status_t status;
    EXPECT_GT(status.decode(empty.data(), 0, static_cast<int>(empty.size())), 0);
}

struct CountingSink {
    int calls = 0;
    std::vector<std::int64_t> seqs;
    void on_block(const lcm::ReceiveBuffer*, const std::string&, const firtp_lcm::block_t* message) {
        ++calls;  // where the component would call validate()
        seqs.push_back(message->seq);
    }
};

// A typed subscription drops what does not decode: the handler, and so validate(), never sees it.
TEST(Decode, GarbageNeverReachesTheHandler) {
    auto lcm = open("memq://");
    CountingSink sink;
    keep_everything(lcm->subscribe(block_channel, &CountingSink::on_block, &sink));

    auto good = encode(test::sample_message(1));
    const auto truncated = std::vector<unsigned char>(good.begin(), good.end() - 1);
    const auto wrong_type = encode(sample_status());
    const std::vector<unsigned char> noise(good.size(), 0xA5);
    lcm->publish(block_channel, truncated.data(), static_cast<unsigned>(truncated.size()));
    lcm->publish(block_channel, wrong_type.data(), static_cast<unsigned>(wrong_type.size()));
    lcm->publish(block_channel, noise.data(), static_cast<unsigned>(noise.size()));
    lcm->publish(block_channel, good.data(), static_cast<unsigned>(good.size()));
    while (lcm->handleTimeout(0) > 0) {
    }
    EXPECT_EQ(sink.calls, 1);
    EXPECT_EQ(sink.seqs, std::vector<std::int64_t>{1});
}

}  // namespace
}  // namespace firtp::messages
