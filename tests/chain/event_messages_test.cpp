// Program events (event_t on FIRTP_EVENT) into the real component through firtp-bridge, in the
// blocks' (program, seq) sequence: each runs exactly once and in order, a damaged one (its crc) is
// refused like a lost one, a gap or repeat is reported, and each is reported on
// FIRTP_EVENT_REACHED when motion reaches it; a dwell rests its length.
#include "chain_fixture.hpp"

#include <firtp/gcode.hpp>
#include <firtp/host.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace firtp;
using test::block_message;

namespace {


struct EventChain : test::Chain {
    std::vector<firtp_lcm::event_t> reached;
    EventChain() : Chain(test::message_machine()) {
        messages::keep_everything(lcm->subscribe(messages::event_reached_channel, &EventChain::on_reached, this));
    }
    void on_reached(const lcm::ReceiveBuffer* b, const std::string& c) { reached.push_back(intact<firtp_lcm::event_t>(b, c)); }
    void event(std::int8_t kind, double value, std::int64_t seq, int line, std::int64_t program = 5) {
        firtp_lcm::event_t e = messages::event_message(kind, value, line, program, seq, 0);
        messages::publish(*lcm, messages::event_channel, e);
    }
    // Longest time (s) the axis states rest exactly at (x, y).
    double rest_at(double x, double y) const {
        double longest = 0.0;
        std::int64_t first = -1;
        for (const auto& s : states) {
            const bool at = s.position[0] == x && s.position[1] == y && s.velocity[0] == 0.0 && s.velocity[1] == 0.0;
            if (at && first < 0) first = s.tick;
            if (!at) first = -1;
            if (at) longest = std::max(longest, static_cast<double>(s.tick - first) * 0.001);
        }
        return longest;
    }
};

}  // namespace

TEST(EventMessages, RunExactlyOnceInOrderAndAreReportedWhenReached) {
    EventChain chain;
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.event(firtp_lcm::event_t::FLOOD_ON, 0, 2, 12);
    chain.event(firtp_lcm::event_t::DWELL, 0.3, 3, 13);
    chain.publish(block_message(10, 10, 5, 4, 14));
    chain.event(firtp_lcm::event_t::PROGRAM_END, 0, 5, 15);
    chain.run(50);
    EXPECT_TRUE(chain.reached.empty());  // motion has not reached them yet
    chain.event(firtp_lcm::event_t::FLOOD_ON, 0, 2, 12);  // a late duplicate: never twice
    chain.run(1500);
    EXPECT_EQ(chain.status().next_seq, 6);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_REPEATED);
    ASSERT_EQ(chain.reached.size(), 3u);
    EXPECT_EQ(chain.reached[0].seq, 2);
    EXPECT_EQ(chain.reached[0].kind, firtp_lcm::event_t::FLOOD_ON);
    EXPECT_EQ(chain.reached[1].seq, 3);
    EXPECT_EQ(chain.reached[2].seq, 5);
    EXPECT_EQ(chain.position()[0], 10.0);
    EXPECT_EQ(chain.position()[1], 10.0);
    const double rest = chain.rest_at(10, 0);
    EXPECT_GE(rest, 0.3);
    EXPECT_LE(rest, 0.3 + 0.002);
}

TEST(EventMessages, ADamagedEventIsRefusedLikeALostOneAndTheResendRunsOnce) {
    EventChain chain;
    chain.publish(block_message(10, 0, 5, 1, 11));
    firtp_lcm::event_t tool = messages::event_message(firtp_lcm::event_t::TOOL_SELECT, 3, 12, 5, 2, 0);
    std::vector<std::uint8_t> bytes = messages::seal_encoded(tool);
    constexpr std::size_t value_at = 8 + 8 + 8 + 8 + 4 + 1;  // fingerprint, utime, program, seq, line, kind
    bytes[value_at + 1] ^= 0x10;
    chain.publish_bytes(messages::event_channel, bytes);
    chain.run(2);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_CORRUPTED);
    EXPECT_NE(chain.status().error_text.find("event seq 2 (line 12): corrupted: CRC mismatch"), std::string::npos)
        << chain.status().error_text;
    EXPECT_EQ(chain.status().next_seq, 2);
    chain.event(firtp_lcm::event_t::TOOL_SELECT, 3, 2, 12);  // the resend
    chain.run(600);
    EXPECT_EQ(chain.status().next_seq, 3);
    ASSERT_EQ(chain.reached.size(), 1u);
    EXPECT_EQ(chain.reached[0].value, 3.0);
}

TEST(EventMessages, AGapBeforeAnEventIsReportedAndNothingAfterItRuns) {
    EventChain chain;
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.event(firtp_lcm::event_t::MIST_ON, 0, 3, 13);  // seq 2 lost
    chain.run(600);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_SEQUENCE_GAP);
    EXPECT_NE(chain.status().error_text.find("expected seq 2"), std::string::npos);
    EXPECT_EQ(chain.status().next_seq, 2);
    EXPECT_TRUE(chain.reached.empty());
}

TEST(EventMessages, AToolChangeWaitsForToolChangedWhichTheChainLoopsBack) {
    EventChain chain;
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.event(firtp_lcm::event_t::TOOL_CHANGE, 2, 2, 12);
    chain.publish(block_message(10, 10, 5, 3, 13));
    chain.run(1500);
    EXPECT_EQ(chain.status().next_seq, 4);
    ASSERT_EQ(chain.reached.size(), 1u);
    EXPECT_EQ(chain.position()[1], 10.0);  // tool-change => tool-changed: motion went on
}

// End to end: the host sends a program's events between its blocks; the dwell rests its length,
// each event is reached once, in order, and the host sees the program done.
TEST(EventMessages, TheHostSendsTheProgramsEventsBetweenItsBlocks) {
    EventChain chain;
    const Program program =
        parse_gcode("G21 G90\nG1 F6000 X10\nG4 P0.3\nM8\nT2 M6\nG1 Y10\nM2\n", "events.ngc", default_machine());
    ASSERT_EQ(program.events.size(), 6u);  // dwell, flood, tool select, tool change, coolant off (M2), end
    host::HostOptions options;
    options.program_id = 9;
    std::int64_t periods = 0;
    options.clock = [&periods] { return host::Clock::time_point(std::chrono::milliseconds(periods)); };
    std::vector<std::int64_t> told;  // what the host hears of them (firtp host prints each)
    options.on_event_reached = [&told](const firtp_lcm::event_t& e) { told.push_back(e.seq); };
    host::Host host(*chain.lcm, program, options);
    for (; periods < 5000 && host.result() == host::Result::running; ++periods) {
        host.step();
        chain.run(1);
    }
    ASSERT_EQ(host.result(), host::Result::done) << host.error();
    EXPECT_EQ(host.statistics().events_published, 6);
    EXPECT_EQ(host.statistics().blocks_published, 2);
    EXPECT_EQ(host.statistics().events_reached, 6);
    ASSERT_EQ(chain.reached.size(), 6u);
    // seq 1 X10, 2 dwell, 3 M8, 4 T2, 5 M6, 6 Y10, 7 M9 (of M2), 8 end: each event once, in order.
    const std::int64_t expected[] = {2, 3, 4, 5, 7, 8};
    for (std::size_t i = 0; i < chain.reached.size(); ++i) EXPECT_EQ(chain.reached[i].seq, expected[i]);
    EXPECT_EQ(told, std::vector<std::int64_t>(std::begin(expected), std::end(expected)));
    EXPECT_EQ(chain.reached[0].kind, firtp_lcm::event_t::DWELL);
    EXPECT_EQ(chain.reached[5].kind, firtp_lcm::event_t::PROGRAM_END);
    const double rest = chain.rest_at(10, 0);
    EXPECT_GE(rest, 0.3);
    EXPECT_LE(rest, 0.3 + 0.005);  // the tool change's handshake adds a period or two
}
