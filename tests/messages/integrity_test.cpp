// The end-to-end CRC of every firtp_lcm message (block_t.lcm): its definition (CRC-32 as zlib's,
// over the encoding without its last 4 bytes, which hold it), seal / intact / receive, and the
// property it is there for: any single-bit (and any two-bit) damage anywhere in an encoded message
// is detected, including the damage LCM's decode lets through as a valid message.
#include "reference_crc32.hpp"
#include "sample.hpp"

#include <cstdio>
#include <cstring>
#include <random>
#include <type_traits>
#include <string>
#include <vector>

namespace firtp::messages {
namespace {

using Bytes = std::vector<std::uint8_t>;
using firtp::test::reference_crc32;
using test::sample_axis_state;
using test::sample_control;
using test::sample_status;





std::uint32_t last_four(const Bytes& bytes) {
    const std::size_t n = bytes.size();
    return std::uint32_t{bytes[n - 4]} << 24 | std::uint32_t{bytes[n - 3]} << 16 | std::uint32_t{bytes[n - 2]} << 8 |
           bytes[n - 1];
}

using test::contains;

// Flips every bit of the sealed message's encoding, one at a time: receive() must report each as
// corrupted. Counts too how many damaged copies LCM alone would have delivered as a valid message
// (they still decode) and, for blocks, how many of those would even pass validate().
template <class Message> void every_single_bit_flip_is_detected(Message message, const char* name) {
    const Bytes sealed = seal_encoded(message);
    ASSERT_TRUE(receive<Message>(sealed.data(), sealed.size()).problem == std::nullopt);
    std::size_t flips = 0, detected = 0, still_decode = 0, still_valid = 0;
    for (std::size_t byte = 0; byte < sealed.size(); ++byte) {
        for (int bit = 0; bit < 8; ++bit) {
            Bytes damaged = sealed;
            damaged[byte] ^= static_cast<std::uint8_t>(1u << bit);
            ++flips;
            const Received<Message> r = receive<Message>(damaged.data(), damaged.size());
            if (r.problem && contains(*r.problem, "corrupted: CRC mismatch")) ++detected;
            else ADD_FAILURE() << name << ": byte " << byte << " bit " << bit << " not detected";
            if (!r.decoded) continue;
            ++still_decode;
            if constexpr (std::is_same_v<Message, firtp_lcm::block_t>) still_valid += !validate(r.message);
        }
    }
    EXPECT_EQ(detected, flips);
    std::printf("%s: %zu bytes, %zu of %zu single-bit flips detected; without the crc %zu would still decode",
                name, sealed.size(), detected, flips, still_decode);
    if constexpr (std::is_same_v<Message, firtp_lcm::block_t>) std::printf(", %zu of them pass validate()", still_valid);
    std::printf("\n");
}

// Every pair of bit flips (CRC-32 has Hamming distance 4 or more at these lengths).
template <class Message> void every_two_bit_flip_is_detected(Message message, const char* name) {
    const Bytes sealed = seal_encoded(message);
    const std::size_t bits = sealed.size() * 8;
    std::size_t pairs = 0, missed = 0;
    Bytes damaged = sealed;
    for (std::size_t a = 0; a < bits; ++a) {
        damaged[a / 8] ^= static_cast<std::uint8_t>(1u << (a % 8));
        for (std::size_t b = a + 1; b < bits; ++b) {
            damaged[b / 8] ^= static_cast<std::uint8_t>(1u << (b % 8));
            ++pairs;
            missed += intact(damaged.data(), damaged.size());
            damaged[b / 8] ^= static_cast<std::uint8_t>(1u << (b % 8));
        }
        damaged[a / 8] ^= static_cast<std::uint8_t>(1u << (a % 8));
    }
    EXPECT_EQ(missed, 0u) << name;
    std::printf("%s: %zu of %zu two-bit flips detected\n", name, pairs - missed, pairs);
}

}  // namespace

// The check value of CRC-32 (IEEE 802.3), what zlib.crc32(b"123456789") and
// java.util.zip.CRC32 give: an lcm-spy user recomputes the crc with those.
TEST(Integrity, Crc32IsZlibsCrc32) {
    const char* check = "123456789";
    EXPECT_EQ(crc32(check, 9), 0xCBF43926u);
    EXPECT_EQ(crc32(nullptr, 0), 0u);
    std::mt19937_64 rng(7);
    for (int n = 0; n < 200; ++n) {
        Bytes bytes(static_cast<std::size_t>(n) * 3);
        for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
        ASSERT_EQ(crc32(bytes.data(), bytes.size()), reference_crc32(bytes.data(), bytes.size())) << n;
    }
}

// seal() sets crc to the CRC-32 of the encoding without its last 4 bytes, and those 4 bytes are
// the crc, big-endian: the definition in block_t.lcm, for each type.
TEST(Integrity, SealSetsTheCrcOfTheEncodingBeforeItsLastFourBytes) {
    auto check = [](auto message) {
        using Message = decltype(message);
        EXPECT_FALSE(intact(message));  // crc 0 (unsealed): not intact
        seal(message);
        EXPECT_TRUE(intact(message));
        Bytes bytes(static_cast<std::size_t>(message.getEncodedSize()));
        message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
        EXPECT_EQ(static_cast<std::uint32_t>(message.crc), reference_crc32(bytes.data(), bytes.size() - 4))
            << Message::getTypeName();
        EXPECT_EQ(last_four(bytes), static_cast<std::uint32_t>(message.crc));
        EXPECT_EQ(seal_encoded(message), bytes);
        const Received<Message> r = receive<Message>(bytes.data(), bytes.size());
        EXPECT_FALSE(r.problem) << *r.problem;
        EXPECT_TRUE(r.decoded);
        EXPECT_EQ(r.message.crc, message.crc);
        EXPECT_EQ(r.message.seq, message.seq);
        message.seq += 1;  // any change after sealing breaks it
        EXPECT_FALSE(intact(message));
    };
    check(test::sample_message());
    check(sample_control());
    check(sample_status());
    check(sample_axis_state());
}

// publish() seals and sends what it sealed; a receiver gets it intact.
TEST(Integrity, PublishSealsWhatItSends) {
    auto lcm = open("memq://");
    std::vector<Received<firtp_lcm::block_t>> got;
    struct Sink {
        std::vector<Received<firtp_lcm::block_t>>* got;
        void on(const lcm::ReceiveBuffer* b, const std::string&) {
            got->push_back(receive<firtp_lcm::block_t>(b->data, b->data_size));
        }
    } sink{&got};
    keep_everything(lcm->subscribe(block_channel, &Sink::on, &sink));
    firtp_lcm::block_t message = test::sample_message(5);
    ASSERT_EQ(publish(*lcm, block_channel, message), 0);
    EXPECT_TRUE(intact(message));  // the caller's copy carries the crc it was sent with
    while (lcm->handleTimeout(0) > 0) {
    }
    ASSERT_EQ(got.size(), 1u);
    EXPECT_FALSE(got[0].problem) << *got[0].problem;
    EXPECT_EQ(got[0].message.seq, 5);
    EXPECT_EQ(got[0].message.crc, message.crc);
}

TEST(Integrity, ReceiveNamesTheProblem) {
    firtp_lcm::block_t block = test::sample_message();
    Bytes bytes = seal_encoded(block);
    const std::uint32_t crc = last_four(bytes);
    bytes[8 + 8 + 8 + 8 - 1] ^= 0x01;  // seq 12 -> 13
    Received<firtp_lcm::block_t> r = receive<firtp_lcm::block_t>(bytes.data(), bytes.size());
    ASSERT_TRUE(r.problem);
    char expected[96];
    std::snprintf(expected, sizeof expected, "corrupted: CRC mismatch (crc 0x%08x, computed 0x%08x)", crc,
                  reference_crc32(bytes.data(), bytes.size() - 4));
    EXPECT_EQ(*r.problem, expected);
    EXPECT_TRUE(r.decoded);  // it still decodes, as a block seq 13: only the crc tells
    EXPECT_EQ(r.message.seq, 13);
    EXPECT_FALSE(validate(r.message));

    const Bytes short_bytes(5, 0);
    r = receive<firtp_lcm::block_t>(short_bytes.data(), short_bytes.size());
    EXPECT_EQ(r.problem, std::optional<std::string>("corrupted: 5 bytes, too short for a firtp_lcm message"));
    EXPECT_FALSE(r.decoded);

    firtp_lcm::status_t status = sample_status();
    const Bytes other = seal_encoded(status);  // intact, but a status on the block channel
    r = receive<firtp_lcm::block_t>(other.data(), other.size());
    ASSERT_TRUE(r.problem);
    EXPECT_TRUE(contains(*r.problem, "intact, but not a block_t of this version (")) << *r.problem;
    EXPECT_FALSE(r.decoded);

    // A block_t from before the crc (as an older host sends it): its own fingerprint, no crc field.
    Bytes old_version = seal_encoded(block);
    old_version.resize(old_version.size() - 4);
    const std::uint8_t old_fingerprint[8] = {0x9e, 0x47, 0x47, 0x86, 0x07, 0xe8, 0xd9, 0x8a};
    std::memcpy(old_version.data(), old_fingerprint, 8);
    r = receive<firtp_lcm::block_t>(old_version.data(), old_version.size());
    ASSERT_TRUE(r.problem);
    EXPECT_TRUE(contains(*r.problem, "corrupted: CRC mismatch (crc 0x")) << *r.problem;
    EXPECT_TRUE(contains(*r.problem, "); its fingerprint 0x9e47478607e8d98a is not block_t's 0x")) << *r.problem;
    EXPECT_TRUE(contains(*r.problem, ": damaged, or another type or version")) << *r.problem;

    Bytes longer = seal_encoded(block);  // a whole block and more: not one block
    longer.insert(longer.end() - 4, 0x00);
    const std::uint32_t fixed = crc32(longer.data(), longer.size() - 4);
    for (std::size_t i = 0; i < 4; ++i) longer[longer.size() - 4 + i] = static_cast<std::uint8_t>(fixed >> (24 - 8 * i));
    r = receive<firtp_lcm::block_t>(longer.data(), longer.size());
    ASSERT_TRUE(r.problem);
    EXPECT_TRUE(contains(*r.problem, "not a block_t")) << *r.problem;
}

// The property the crc is for: every single-bit flip anywhere in an encoded message, among them
// those that still decode as a valid message with another target, feed, seq or feed override.
TEST(Integrity, EverySingleBitFlipOfABlockIsDetected) {
    every_single_bit_flip_is_detected(test::sample_message(), "block_t");
}
TEST(Integrity, EverySingleBitFlipOfAControlIsDetected) {
    every_single_bit_flip_is_detected(sample_control(), "control_t");
}
// Including the string's terminating \0, which decode does not read (a re-encoded copy would hide it).
TEST(Integrity, EverySingleBitFlipOfAStatusIsDetected) {
    every_single_bit_flip_is_detected(sample_status(), "status_t");
}
TEST(Integrity, EverySingleBitFlipOfAnAxisStateIsDetected) {
    every_single_bit_flip_is_detected(sample_axis_state(), "axis_state_t");
}

TEST(Integrity, EveryTwoBitFlipOfABlockOrControlIsDetected) {
    every_two_bit_flip_is_detected(test::sample_message(), "block_t");
    every_two_bit_flip_is_detected(sample_control(), "control_t");
}

}  // namespace firtp::messages
