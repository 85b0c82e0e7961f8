// Writes the seed inputs of fuzz_lcm (tests/fuzz/corpus/lcm) in its format: messages as
// [kind][length, 2 bytes big-endian][encoded LCM message], sealed (their crc matches) unless a
// seed damages them on purpose. Run again when the .lcm types change:
//   build-fuzz/bin/make_lcm_seeds tests/fuzz/corpus/lcm
// The regression-* seeds are the inputs that found defects, rebuilt here with the current types:
// the same values, sealed, so they pass the crc gate and reach the code they found the defect in.
#include <firtp/messages.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

void frame(Bytes& out, std::uint8_t kind, const Bytes& bytes) {
    const std::size_t n = bytes.size();
    out.push_back(kind);
    out.push_back(static_cast<std::uint8_t>(n >> 8));
    out.push_back(static_cast<std::uint8_t>(n & 0xff));
    out.insert(out.end(), bytes.begin(), bytes.end());
}

// The CRC-32 of all but the last 4 bytes into the last 4: what seal() does, on bytes.
void reseal(Bytes& bytes) {
    const std::uint32_t crc = firtp::messages::crc32(bytes.data(), bytes.size() - 4);
    for (std::size_t i = 0; i < 4; ++i) bytes[bytes.size() - 4 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
}

// Sealed, as every sender sends it.
template <typename M> void add(Bytes& out, std::uint8_t kind, M message) {
    frame(out, kind, firtp::messages::seal_encoded(message));
}

// Sealed, then changed by `damage` and sealed again: bytes the generated encode cannot make, with a
// matching crc (a sender's defect, not the link's).
template <typename M> void add_patched(Bytes& out, std::uint8_t kind, M message, const std::function<void(Bytes&)>& damage) {
    Bytes bytes = firtp::messages::seal_encoded(message);
    damage(bytes);
    reseal(bytes);
    frame(out, kind, bytes);
}

// Sealed, then damaged in transit: the crc no longer matches.
template <typename M> void add_damaged(Bytes& out, std::uint8_t kind, M message, const std::function<void(Bytes&)>& damage) {
    Bytes bytes = firtp::messages::seal_encoded(message);
    damage(bytes);
    frame(out, kind, bytes);
}

void ticks(Bytes& out, int periods) {
    out.push_back(2);
    out.push_back(static_cast<std::uint8_t>(periods >> 8));
    out.push_back(static_cast<std::uint8_t>(periods & 0xff));
}

firtp_lcm::block_t block(double x, double y, std::int64_t program, std::int64_t seq) {
    firtp::Block b;
    b.target[0] = x;
    b.target[1] = y;
    b.feed = 100;
    b.tolerance = 0.05;
    b.line = seq + 10;
    return firtp::messages::to_message(b, program, seq, 1);
}

firtp_lcm::control_t control(std::int64_t seq, double feed, bool hold, bool abort) {
    firtp_lcm::control_t c{};
    c.session = 1;
    c.seq = seq;
    c.feed_scale = feed;
    c.hold = hold;
    c.abort = abort;
    return c;
}

void write(const std::string& dir, const std::string& name, const Bytes& bytes) {
    std::ofstream(dir + "/" + name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                            static_cast<std::streamsize>(bytes.size()));
}

constexpr std::size_t block_target_at = 8 + 8 + 8 + 8 + 4 + 1 + 1;       // fingerprint, utime, program, seq, line, kinds
constexpr std::size_t block_feed_at = block_target_at + 9 * 8;
constexpr std::size_t control_feed_scale_at = 8 + 8 + 8 + 8;             // fingerprint, utime, session, seq
constexpr std::size_t status_text_length_at = 8 + 5 * 8 + 3 * 4 + 1 + 8 + 4;

}  // namespace

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : ".";
    Bytes diamond;  // four blocks, run to the end
    add(diamond, 0, block(25, 25, 7, 1));
    add(diamond, 0, block(50, 0, 7, 2));
    add(diamond, 0, block(25, -25, 7, 3));
    add(diamond, 0, block(0, 0, 7, 4));
    ticks(diamond, 400);
    write(dir, "diamond", diamond);

    Bytes faults;  // a repeat, a gap, a NaN, then a new program
    add(faults, 0, block(5, 0, 3, 1));
    add(faults, 0, block(5, 0, 3, 1));
    add(faults, 0, block(5, 5, 3, 3));
    firtp_lcm::block_t nan = block(0, 5, 3, 2);
    nan.feed = std::numeric_limits<double>::quiet_NaN();
    add(faults, 0, nan);
    ticks(faults, 100);
    add(faults, 0, block(1, 1, 4, 1));
    ticks(faults, 50);
    write(dir, "faults", faults);

    Bytes operator_controls;  // override, hold, resume, abort, a new program
    add(operator_controls, 0, block(30, 0, 9, 1));
    add(operator_controls, 0, block(30, 30, 9, 2));
    add(operator_controls, 1, control(1, 1.5, false, false));
    ticks(operator_controls, 50);
    add(operator_controls, 1, control(2, 1.0, true, false));
    ticks(operator_controls, 100);
    add(operator_controls, 1, control(3, 1.0, false, true));
    ticks(operator_controls, 300);
    add(operator_controls, 1, control(4, 1.0, false, false));
    add(operator_controls, 0, block(0, 0, 10, 1));
    ticks(operator_controls, 100);
    write(dir, "operator", operator_controls);

    Bytes host_side;  // what the host decodes
    firtp_lcm::status_t s{};
    s.seq = 5;
    s.program = 7;
    s.next_seq = 3;
    s.state = firtp_lcm::status_t::MOVING;
    s.error_text = "block seq 2 (line 12): feed is NaN";
    add(host_side, 3, s);
    firtp_lcm::axis_state_t a{};
    a.seq = 1;
    a.tick = 10;
    a.position[0] = 1.5;
    add(host_side, 3, a);
    write(dir, "host_side", host_side);

    // Damaged in transit (the crc gate): a block whose X target, one whose feed and one whose seq
    // lost a bit, a truncated one, a control whose feed override lost one; then the intact ones.
    Bytes corrupted;
    add(corrupted, 0, block(25, 25, 7, 1));
    add_damaged(corrupted, 0, block(50, 0, 7, 2), [](Bytes& b) { b[block_target_at + 1] ^= 0x10; });
    add_damaged(corrupted, 0, block(50, 0, 7, 2), [](Bytes& b) { b[block_feed_at + 2] ^= 0x01; });
    add_damaged(corrupted, 0, block(25, -25, 7, 3), [](Bytes& b) { b[8 + 8 + 8 + 7] ^= 0x01; });  // seq 3 -> 2
    add_damaged(corrupted, 0, block(50, 0, 7, 2), [](Bytes& b) { b.resize(b.size() - 5); });
    add_damaged(corrupted, 1, control(1, 1.0, false, false), [](Bytes& b) { b[control_feed_scale_at] ^= 0x40; });
    add(corrupted, 1, control(1, 1.0, false, false));
    ticks(corrupted, 20);
    add(corrupted, 0, block(50, 0, 7, 2));
    add(corrupted, 0, block(25, -25, 7, 3));
    add(corrupted, 0, block(0, 0, 7, 4));
    ticks(corrupted, 400);
    write(dir, "corrupted", corrupted);

    // kind | 4: the harness seals the bytes (these are not): payloads it changes reach decode and
    // validate with a matching crc.
    Bytes harness_sealed;
    for (std::int64_t seq = 1; seq <= 3; ++seq) {
        firtp_lcm::block_t b = block(10.0 * static_cast<double>(seq), 0, 11, seq);
        b.crc = 0;
        Bytes bytes(static_cast<std::size_t>(b.getEncodedSize()));
        b.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
        frame(harness_sealed, 4, bytes);
    }
    firtp_lcm::control_t c = control(1, 0.5, false, false);
    Bytes control_bytes(static_cast<std::size_t>(c.getEncodedSize()));
    c.encode(control_bytes.data(), 0, static_cast<int>(control_bytes.size()));
    frame(harness_sealed, 5, control_bytes);
    ticks(harness_sealed, 300);
    write(dir, "harness_sealed", harness_sealed);

    // Found by fuzz_lcm: a feed (and tolerance) of about 1e-315 after two blocks gave undefined
    // behaviour in the planner (a duration beyond any integer). The values of the input that found it.
    Bytes tiny_feed;
    firtp_lcm::block_t first = block(25, 25, 7, 1);
    first.target[2] = std::bit_cast<double>(std::uint64_t{0x000000f100000000});
    add(tiny_feed, 0, first);
    add(tiny_feed, 0, block(50, 0, 7, 2));
    firtp_lcm::block_t tiny = block(25.125, 0, 7, 3);
    tiny.target[1] = std::bit_cast<double>(std::uint64_t{0x00000000c0390000});
    tiny.feed = std::bit_cast<double>(std::uint64_t{0x0000000040590000});
    tiny.tolerance = std::bit_cast<double>(std::uint64_t{0x000000003fa99999});
    add(tiny_feed, 0, tiny);
    write(dir, "regression-feed-1e-300", tiny_feed);

    // Found by fuzz_lcm: a status_t whose error_text length is 0 (lcm-gen 1.3.1's decode threw
    // std::length_error through LCM; -1 and INT32_MIN too; lcm-types/fix_string_decode.cmake). Intact,
    // so the decode sees the length.
    Bytes string_length;
    firtp_lcm::status_t bad{};
    bad.seq = 5;
    bad.tick = 23904663482862;
    bad.next_seq = 5;
    bad.feed_scale = std::bit_cast<double>(std::uint64_t{0x0000070000000000});
    bad.error_code = 768;
    bad.error_text = "block seq 2 (line 12): feed is NaN";
    for (std::uint32_t length : {0u, 0xFFFFFFFFu, 0x80000000u}) {
        add_patched(string_length, 3, bad, [length](Bytes& b) {
            for (std::size_t i = 0; i < 4; ++i)
                b[status_text_length_at + i] = static_cast<std::uint8_t>(length >> (24 - 8 * i));
        });
        ticks(string_length, 314);
    }
    add(string_length, 3, a);
    write(dir, "regression-status-string-length-0", string_length);
    return 0;
}
