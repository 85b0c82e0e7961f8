// Writes the seed inputs of fuzz_lcm (tests/fuzz/corpus/lcm) in its format: messages as
// [kind][length, 2 bytes big-endian][encoded LCM message]. Run again when the .lcm types change:
//   build-fuzz/bin/make_lcm_seeds tests/fuzz/corpus/lcm
#include <firtp/messages.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

template <typename M>
void add(Bytes& out, std::uint8_t kind, const M& message) {
    const int n = message.getEncodedSize();
    Bytes buffer(static_cast<std::size_t>(n));
    message.encode(buffer.data(), 0, n);
    out.push_back(kind);
    out.push_back(static_cast<std::uint8_t>(n >> 8));
    out.push_back(static_cast<std::uint8_t>(n & 0xff));
    out.insert(out.end(), buffer.begin(), buffer.end());
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
    return 0;
}
