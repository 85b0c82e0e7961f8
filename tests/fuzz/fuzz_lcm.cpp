// libFuzzer target: LCM message handling on the component side, as firtp-bridge and firtp.update
// do it. The input is a sequence of messages, each [kind][length, 2 bytes big-endian][bytes]:
//   kind % 4 == 0: a FIRTP_BLOCK message -> decode, messages::validate, the exactly-once
//                  SequenceChecker, then the component's block stream (ComponentCore accepts it)
//   kind % 4 == 1: a FIRTP_CONTROL message -> decode, the bridge's checks, the control pins
//   kind % 4 == 2: run the servo thread for (length % 512) periods, no bytes
//   kind % 4 == 3: a FIRTP_STATUS or FIRTP_AXIS_STATE message -> decode (what the host reads)
// Checked: decoding never reads out of bounds; a message that validates is never refused by the
// planner as a bad value (unless its feed is below 1e-3: the planner refuses a pulse longer than
// its clock, 1e16 periods); the component's output stays finite; the blocks it runs are exactly
// the ones the sequence checker passed, once each, in order (next_seq).
#include <component_core.hpp>
#include <firtp/messages.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

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
    s.planner.filters.stages = 2;
    s.planner.filters.T = {0.02, 0.01, 0.0, 0.0};
    s.planner.period = 0.001;
    s.planner.max_rate = 2.0;
    s.queue = 256;  // the stream (64) always drains within two periods
    return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const firtp::ComponentSettings component_settings = settings();
    firtp::ComponentCore core(component_settings);
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
        const std::uint8_t* bytes = data + pos;
        pos += n;
        switch (kind % 4) {
        case 0: {
            firtp_lcm::block_t m;
            if (m.decode(bytes, 0, static_cast<int>(n)) < 0) break;
            if (firtp::messages::validate(m)) break;  // refused, with a reason
            if (in.abort) break;                      // the bridge refuses blocks while abort is set
            const bool idle = out.done && ring.count == 0 && out.mode != firtp::ComponentState::aborting;
            if (sequence.check(m.program, m.seq, idle) != firtp::messages::SequenceChecker::Verdict::accept) break;
            if (ring.count == ring.records.size()) break;  // the bridge reports "stream full, resend"
            firtp::stream::BlockRecord r;
            r.block = firtp::messages::to_block(m);
            r.program = static_cast<std::uint32_t>(m.program);
            r.seq = static_cast<std::uint32_t>(m.seq);
            ring.records[(ring.head + ring.count++) % ring.records.size()] = r;
            slow = slow || m.feed < 1e-3;
            if (m.program != sequence.program()) aborted = false;
            sequence.accepted(m.program, m.seq);
            break;
        }
        case 1: {
            firtp_lcm::control_t m;
            if (m.decode(bytes, 0, static_cast<int>(n)) < 0) break;
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
            firtp_lcm::status_t s;
            firtp_lcm::axis_state_t a;
            if (s.decode(bytes, 0, static_cast<int>(n)) < 0) (void)a.decode(bytes, 0, static_cast<int>(n));
            break;
        }
        }
    }
    tick(2);
    require(ring.count == 0);
    // Exactly once: every block the sequence checker passed was accepted by the component, in order.
    if (sequence.program() != 0 && !aborted && !slow) {
        require(out.program == static_cast<std::uint32_t>(sequence.program()));
        require(out.next_seq == static_cast<std::uint32_t>(sequence.next_seq()));
    }
    return 0;
}
