// The LCM side of firtp: channels, opening a transport, and turning messages into blocks with
// every check a machine needs (finite values, ranges, known types, sequence).
#pragma once

#include <firtp/types.hpp>
#include <firtp_lcm/axis_state_t.hpp>
#include <firtp_lcm/block_t.hpp>
#include <firtp_lcm/config_t.hpp>
#include <firtp_lcm/control_t.hpp>
#include <firtp_lcm/event_t.hpp>
#include <firtp_lcm/status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace firtp::messages {

inline constexpr const char* block_channel = "FIRTP_BLOCK";
inline constexpr const char* status_channel = "FIRTP_STATUS";
inline constexpr const char* axis_state_channel = "FIRTP_AXIS_STATE";            // every servo period
inline constexpr const char* axis_state_live_channel = "FIRTP_AXIS_STATE_LIVE";  // decimated
inline constexpr const char* control_channel = "FIRTP_CONTROL";
inline constexpr const char* config_channel = "FIRTP_CONFIG";  // machine and settings (config_t)
inline constexpr const char* event_channel = "FIRTP_EVENT";    // program events, host -> component (event_t)
inline constexpr const char* event_reached_channel = "FIRTP_EVENT_REACHED";  // each as motion reaches it

// How often the component side publishes, by default (every bridge): FIRTP_AXIS_STATE_LIVE every
// N servo periods, FIRTP_STATUS every N periods and on every change.
inline constexpr int default_live_decimation = 20;
inline constexpr int default_status_every = 10;

// LCM's default multicast group with ttl=0 (this host only) and an 8 MiB receive buffer.
std::string default_url();

// Opens a transport; for udpm:// URLs without recv_buf_size, adds 8 MiB (LCM 1.3.1 loses fast
// streams otherwise). Throws std::runtime_error naming the URL when LCM cannot start (e.g. no
// multicast route).
std::unique_ptr<lcm::LCM> open(const std::string& url);

// Raises a subscription's queue to unbounded (LCM 1.3.1 defaults to 30 and drops the rest).
void keep_everything(lcm::Subscription* subscription);

firtp_lcm::block_t to_message(const Block& block, std::int64_t program, std::int64_t seq, std::int64_t utime);

// Empty when the message can be planned; otherwise what is wrong, naming seq and line, e.g.
// "block seq 12 (line 40): feed is NaN". Checks: finite target, feed > 0 and finite, tolerance > 0
// or +inf, known motion type (1, 2) and termination (0, 1), seq >= 1, |target| <= 1e6.
std::optional<std::string> validate(const firtp_lcm::block_t& message);

// "block seq N (line L)": how every error about one block message names it.
std::string describe(const firtp_lcm::block_t& message);

// A program event (kind: event_t's constants, the values of firtp::EventKind).
firtp_lcm::event_t event_message(std::int8_t kind, double value, std::int64_t line, std::int64_t program,
                                 std::int64_t seq, std::int64_t utime);
// Empty when the event may run: seq >= 1, a known kind, a finite value, a dwell of 0 .. max_dwell s.
std::optional<std::string> validate(const firtp_lcm::event_t& message);
std::string describe(const firtp_lcm::event_t& message);  // "event seq N (line L)"

// Wall-clock microseconds since the epoch, LCM's utime convention.
std::int64_t now_utime();

// ---- Integrity, end to end (lcm-types/README.md, "Integrity") ----
// Senders seal (or publish(), which seals); receivers take the bytes as received to receive(),
// which checks the crc before it decodes.

// CRC-32 of `size` bytes.
std::uint32_t crc32(const void* data, std::size_t size);

// Encoded bytes as received: at least fingerprint and crc, and the last 4 bytes (big-endian) equal
// the CRC-32 of the others.
bool intact(const void* data, std::size_t size);

// "corrupted: CRC mismatch (crc 0x0badf00d, computed 0x12345678)", or for fewer than 12 bytes
// "corrupted: 5 bytes, too short for a firtp_lcm message"; empty when intact.
std::optional<std::string> integrity_problem(const void* data, std::size_t size);

// Sets message.crc and returns the message's encoding (with that crc).
template <class Message> std::vector<std::uint8_t> seal_encoded(Message& message) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
    const int n = static_cast<int>(bytes.size());
    message.crc = 0;
    message.encode(bytes.data(), 0, n);
    const std::uint32_t crc = crc32(bytes.data(), bytes.size() - 4);
    message.crc = static_cast<std::int32_t>(crc);
    for (std::size_t i = 0; i < 4; ++i) bytes[bytes.size() - 4 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
    return bytes;
}

// Sets message.crc: call after the last change to any other field, before it is sent or written.
template <class Message> void seal(Message& message) { (void)seal_encoded(message); }

// The message's encoding, as it is now, is intact (its crc matches its fields).
template <class Message> bool intact(const Message& message) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    return intact(bytes.data(), bytes.size());
}

// Seals the message and publishes that encoding; LCM's publish result (0 on success).
template <class Message> int publish(lcm::LCM& lcm, const std::string& channel, Message& message) {
    const std::vector<std::uint8_t> bytes = seal_encoded(message);
    return lcm.publish(channel, bytes.data(), static_cast<unsigned int>(bytes.size()));
}

// The live view for lcm-spy: publishes `state` on FIRTP_AXIS_STATE_LIVE when its tick is a multiple
// of `decimation` (0: never), with seq tick / decimation (so a gap there is a lost message too).
// True when it published.
bool publish_live(lcm::LCM& lcm, firtp_lcm::axis_state_t state, int decimation);

// For intact bytes that are not exactly one message of the type:
// "intact, but not a block_t of this version (120 bytes, fingerprint 0x0123456789abcdef)".
std::string not_this_type(const void* data, std::size_t size, const char* type);

// For damaged bytes whose fingerprint is not the type's (a sender of another version shows so):
// "; its fingerprint 0x0123456789abcdef is not block_t's 0x...: damaged, or another type or
// version", or "" when it is the type's.
std::string fingerprint_note(const void* data, std::size_t size, const char* type, std::int64_t hash);

template <class Message> struct Received {
    Message message{};                   // decoded; to be trusted only when there is no problem
    bool decoded = false;                // the bytes decode as a Message (if corrupted: only to name it)
    std::optional<std::string> problem;  // empty: intact, and exactly one Message
};

// What every receiver does first with the bytes LCM delivered: the crc, then the decode. The
// problem is integrity_problem()'s (with fingerprint_note() when the bytes do not decode), or
// not_this_type()'s for intact bytes of another type.
template <class Message> Received<Message> receive(const void* data, std::size_t size) {
    Received<Message> r;
    r.problem = integrity_problem(data, size);
    const int n = size > 0x7fffffff ? -1 : static_cast<int>(size);
    r.decoded = n >= 0 && r.message.decode(data, 0, n) == n;
    if (!r.problem && !r.decoded) r.problem = not_this_type(data, size, Message::getTypeName());
    else if (r.problem && !r.decoded) *r.problem += fingerprint_note(data, size, Message::getTypeName(), Message::getHash());
    return r;
}

// Valid message -> block (call validate first).
Block to_block(const firtp_lcm::block_t& message);

// Exactly-once, in-order acceptance of (program, seq) (lcm-types/README.md, "Exactly once").
class SequenceChecker {
public:
    enum class Verdict {
        accept,        // seq == next_seq of the current program, or seq 1 of a new program when allowed
        repeated,      // seq < next_seq, or an older program: already accepted, must not run again
        gap,           // seq > next_seq: something was lost or reordered; the host resends from next_seq
        busy,          // a new program while the previous one still has blocks queued
    };
    // new_program_allowed: the component is idle (nothing queued), so a new program id may start.
    Verdict check(std::int64_t program, std::int64_t seq, bool new_program_allowed) const;
    void accepted(std::int64_t program, std::int64_t seq);  // after the block was really queued
    std::int64_t program() const { return program_; }
    std::int64_t next_seq() const { return next_seq_; }
    static const char* describe(Verdict verdict);

private:
    std::int64_t program_ = 0;
    std::int64_t next_seq_ = 1;
};

}  // namespace firtp::messages
