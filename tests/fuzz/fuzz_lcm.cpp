// libFuzzer target: LCM message handling on the component side, as firtp-bridge and firtp.update
// do it. The input is a sequence of messages, each [kind][length, 2 bytes big-endian][bytes]:
//   kind % 4 == 0: a FIRTP_BLOCK message -> messages::receive (the crc of the bytes as received,
//                  then the decode), messages::validate, the exactly-once SequenceChecker, then the
//                  component's block stream (ComponentLogic accepts it)
//   kind % 4 == 1: a FIRTP_CONTROL message -> messages::receive, the bridge's checks, the control pins
//   kind % 4 == 2: run the servo thread for (length % 512) periods, no bytes
//   kind % 4 == 3: a FIRTP_STATUS or FIRTP_AXIS_STATE message -> messages::receive (what the host reads)
//   kind & 4, for messages: the harness seals the bytes first (writes the CRC-32 of all but the last
//                  4 bytes into them), as a sender would that sealed whatever it built; without it
//                  the bytes go as they are, and only an intact message passes. (So mutated
//                  payloads still reach decode and validate, and damaged ones test the crc gate.)
// Checked: the crc gate agrees with a CRC-32 computed here bit by bit (independent of Boost):
// bytes whose crc does not match are refused as "corrupted", and no block or control with a bad
// crc ever reaches the planner or the control pins; decoding never reads out of bounds; a message
// that validates is never refused by the planner as a bad value (unless its feed is below 1e-3:
// the planner refuses a pulse longer than its clock, 1e16 periods); the component's output stays
// finite; the blocks it runs are exactly the ones the sequence checker passed, once each, in order
// (next_seq).
#include <firtp/hal/component_logic.hpp>
#include <firtp/messages.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../messages/reference_crc32.hpp"
#include "require.hpp"

namespace {

struct Ring {
    std::array<firtp::stream::BlockRecord, 64> records{};
    std::size_t head = 0, count = 0;
    static bool read(void* self, firtp::stream::BlockRecord& r) {
        auto* s = static_cast<Ring*>(self);
        if (s->count == 0) return false;
        r = s->records[s->head];
        s->head = (s->head + 1) % s->records.size();
        --s->count;
        return true;
    }
};

firtp::ComponentSettings settings() {
    firtp::ComponentSettings s;
    s.planner.fixed_chain = true;  // the paper's chain: no machine limits needed
    s.planner.filters.stages = 2;
    s.planner.filters.T = {0.02, 0.01, 0.0, 0.0};
    s.planner.period = 0.001;
    s.planner.max_rate = 2.0;
    s.planner.queue_capacity = 256;  // the stream (64) always drains within two periods
    return s;
}

using firtp::test::reference_crc32;

// The definition in block_t.lcm: the last 4 bytes, big-endian, are the CRC-32 of the others.
bool reference_intact(const std::vector<std::uint8_t>& bytes) {
    const std::size_t n = bytes.size();
    if (n < 12) return false;
    const std::uint32_t sent = std::uint32_t{bytes[n - 4]} << 24 | std::uint32_t{bytes[n - 3]} << 16 |
                               std::uint32_t{bytes[n - 2]} << 8 | std::uint32_t{bytes[n - 1]};
    return sent == reference_crc32(bytes.data(), n - 4);
}

void reseal(std::vector<std::uint8_t>& bytes) {
    const std::size_t n = bytes.size();
    if (n < 12) return;
    const std::uint32_t crc = reference_crc32(bytes.data(), n - 4);
    for (std::size_t i = 0; i < 4; ++i) bytes[n - 4 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
}

bool corrupted(const std::optional<std::string>& problem) {
    return problem && problem->rfind("corrupted: ", 0) == 0;
}

// The gate agrees with the reference: a bad crc is "corrupted", an intact message of the type passes.
template <class Message>
firtp::messages::Received<Message> receive_checked(const std::vector<std::uint8_t>& bytes) {
    const auto r = firtp::messages::receive<Message>(bytes.data(), bytes.size());
    const bool intact = reference_intact(bytes);
    require(corrupted(r.problem) == !intact);
    require(!r.problem || !r.problem->empty());
    if (intact) require(!r.problem == r.decoded);  // intact: refused only when it is not one Message
    return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const firtp::ComponentSettings component_settings = settings();
    firtp::ComponentLogic core(component_settings);
    firtp::messages::SequenceChecker sequence;
    Ring ring;
    firtp::ComponentInputs in;
    firtp::ComponentOutputs out;
    bool aborted = false;  // an abort since the current program started: its queued blocks were dropped
    bool slow = false;     // a block with a feed below 1e-3 was passed: the planner may refuse it

    auto tick = [&](int periods) {
        for (int k = 0; k < periods; ++k) {
            core.update(in, {Ring::read, &ring}, out);
            require(out.state.position.allFinite() && out.state.velocity.allFinite() &&
                  out.state.acceleration.allFinite());
            require(out.error != firtp::ComponentError::bad_type);
            require(slow || out.error != firtp::ComponentError::bad_value);
        }
    };

    std::size_t pos = 0;
    while (pos + 3 <= size) {
        const std::uint8_t kind = data[pos];
        const std::size_t length = static_cast<std::size_t>(data[pos + 1]) << 8 | data[pos + 2];
        pos += 3;
        const std::size_t n = kind % 4 == 2 ? 0 : std::min(length, size - pos);
        std::vector<std::uint8_t> bytes(data + pos, data + pos + n);
        pos += n;
        if (kind & 4) reseal(bytes);
        switch (kind % 4) {
        case 0: {
            const auto received = receive_checked<firtp_lcm::block_t>(bytes);
            if (received.problem) break;  // refused: corrupted (as if lost), or not a block_t
            require(reference_intact(bytes));  // nothing with a bad crc goes on towards the planner
            const firtp_lcm::block_t& m = received.message;
            if (firtp::messages::validate(m)) break;  // refused, with a reason
            if (in.abort) break;                      // the bridge refuses blocks while abort is set
            const bool idle = out.done && ring.count == 0 && out.mode != firtp::ComponentState::aborting;
            if (sequence.check(m.program, m.seq, idle) != firtp::messages::SequenceChecker::Verdict::accept) break;
            if (ring.count == ring.records.size()) break;  // the bridge reports "stream full, resend"
            firtp::stream::BlockRecord r;
            r.block = firtp::messages::to_block(m);
            r.program = static_cast<std::uint64_t>(m.program);  // all 64 bits, as the bridge
            r.seq = static_cast<std::uint64_t>(m.seq);
            ring.records[(ring.head + ring.count++) % ring.records.size()] = r;
            slow = slow || m.feed < 1e-3;
            if (m.program != sequence.program()) aborted = false;
            sequence.accepted(m.program, m.seq);
            break;
        }
        case 1: {
            const auto received = receive_checked<firtp_lcm::control_t>(bytes);
            if (received.problem) break;  // ignored: the levels in effect stay
            require(reference_intact(bytes));  // no bad crc reaches the control pins
            const firtp_lcm::control_t& m = received.message;
            if (std::isfinite(m.feed_scale) && m.feed_scale >= 0.0) in.feed_scale = std::min(m.feed_scale, 2.0);
            in.hold = m.hold;
            in.abort = m.abort;
            aborted = aborted || m.abort;
            break;
        }
        case 2:
            tick(static_cast<int>(length % 512));
            break;
        case 3: {
            if (receive_checked<firtp_lcm::status_t>(bytes).problem) (void)receive_checked<firtp_lcm::axis_state_t>(bytes);
            break;
        }
        }
    }
    tick(2);
    require(ring.count == 0);
    // Exactly once: every block the sequence checker passed was accepted by the component, in order.
    if (sequence.program() != 0 && !aborted && !slow) {
        require(out.program == static_cast<std::uint64_t>(sequence.program()));
        require(out.next_seq == static_cast<std::uint64_t>(sequence.next_seq()));
    }
    return 0;
}
