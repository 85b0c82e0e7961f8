// Block -> block_t -> Block, directly and through the encoded bytes.
#include "sample.hpp"

#include <limits>
#include <vector>

namespace firtp::messages {
namespace {

using test::sample_block;

void expect_same(const Block& a, const Block& b) {
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.feed, b.feed);
    EXPECT_EQ(a.termination, b.termination);
    EXPECT_EQ(a.tolerance, b.tolerance);
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.line, b.line);
}

TEST(Conversion, MessageCarriesEveryField) {
    const auto message = to_message(sample_block(), 7, 12, 123456);
    EXPECT_EQ(message.utime, 123456);
    EXPECT_EQ(message.program, 7);
    EXPECT_EQ(message.seq, 12);
    EXPECT_EQ(message.line, 40);
    EXPECT_EQ(message.motion_type, 2);
    EXPECT_EQ(message.termination, 1);
    for (int axis = 0; axis < max_axes; ++axis) EXPECT_EQ(message.target[axis], sample_block().target[axis]);
    EXPECT_EQ(message.feed, 25.0);
    EXPECT_EQ(message.tolerance, 0.02);
}

TEST(Conversion, RoundTrip) {
    Block block = sample_block();
    expect_same(to_block(to_message(block, 1, 1, 0)), block);

    block.type = MotionType::traverse;
    block.termination = Termination::exact_stop;
    block.tolerance = 0.5;
    block.target[5] = -1e6;
    block.line = 0;
    expect_same(to_block(to_message(block, 1, 2, 0)), block);

    block.termination = Termination::blend;
    block.tolerance = std::numeric_limits<double>::infinity();  // G64 P0: no limit
    expect_same(to_block(to_message(block, 1, 3, 0)), block);
}

TEST(Conversion, RoundTripThroughBytes) {
    const Block block = sample_block();
    const auto sent = to_message(block, 3, 9, 42);
    std::vector<unsigned char> bytes(static_cast<std::size_t>(sent.getEncodedSize()));
    ASSERT_EQ(sent.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));

    firtp_lcm::block_t received;
    ASSERT_EQ(received.decode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
    ASSERT_EQ(validate(received), std::nullopt);
    EXPECT_EQ(received.program, 3);
    EXPECT_EQ(received.seq, 9);
    expect_same(to_block(received), block);
}

// The G-code reader gives G61 blocks tolerance 0; the wire needs > 0, and an exact stop ignores it.
TEST(Conversion, ExactStopWithoutToleranceSendsInfinity) {
    Block block = sample_block();
    block.termination = Termination::exact_stop;
    block.tolerance = 0.0;
    const auto message = to_message(block, 1, 1, 0);
    EXPECT_EQ(message.tolerance, std::numeric_limits<double>::infinity());
    EXPECT_EQ(validate(message), std::nullopt);
    EXPECT_EQ(to_block(message).termination, Termination::exact_stop);
}

TEST(Conversion, BlendWithoutToleranceStaysInvalid) {
    Block block = sample_block();
    block.tolerance = 0.0;
    EXPECT_NE(validate(to_message(block, 1, 1, 0)), std::nullopt);
}

TEST(Conversion, LineBeyondInt32IsClamped) {
    Block block = sample_block();
    block.line = std::int64_t{1} << 40;
    EXPECT_EQ(to_message(block, 1, 1, 0).line, std::numeric_limits<std::int32_t>::max());
}

}  // namespace
}  // namespace firtp::messages
