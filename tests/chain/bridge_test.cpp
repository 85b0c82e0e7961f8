// LCM messages into the real component through firtp-bridge: bad values, gaps, repeats,
// reordering and corrupted messages (their crc) are reported in FIRTP_STATUS, and no block runs
// twice or is dropped silently.
#include "chain_fixture.hpp"

#include <firtp/hal/control_pins.hpp>
#include <firtp/hal/stream_records.hpp>
#include <firtp/host.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace firtp;
using test::block_message;

// The bridge falls behind twice (firtp.so's 50-period axis-state stream overflows): every
// missing period is a gap in the ticks, and the latest status counts them all, as the pin
// firtp.state-overruns does (a LinuxCNC integrator compares the two).
TEST(Bridge, StatesLostTwiceAreCountedInAll) {
    InProcessSettings settings;
    settings.stream_depth = 50;
    test::Chain chain(test::message_machine(), settings);
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.run(5);
    for (const int behind : {80, 61}) {
        for (int k = 0; k < behind; ++k) chain.chain->step();  // the bridge not polled
        chain.run(5);
    }
    std::int64_t missing = 0, gaps = 0, latest = 0, latest_tick = 0;
    for (std::size_t i = 1; i < chain.states.size(); ++i) {
        const std::int64_t gap = chain.states[i].tick - chain.states[i - 1].tick - 1;
        if (gap == 0) continue;
        ++gaps, missing += gap, latest = gap, latest_tick = chain.states[i].tick;
    }
    EXPECT_EQ(gaps, 2);
    EXPECT_GT(latest, 0);
    EXPECT_GT(missing, latest);
    ASSERT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_LOST_STATE);
    EXPECT_EQ(chain.status().error_text, std::to_string(missing) + " axis states lost, the latest " + std::to_string(latest) +
                                             " before tick " + std::to_string(latest_tick) +
                                             " (the bridge fell behind the servo thread)");
}

TEST(Bridge, RunsAProgramAndReportsProgress) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.publish(block_message(10, 10, 5, 2, 12));
    chain.run(400);
    EXPECT_EQ(chain.status().next_seq, 3);
    EXPECT_EQ(chain.status().program, 5);
    EXPECT_EQ(chain.status().state, firtp_lcm::status_t::IDLE);
    EXPECT_EQ(chain.status().error_code, 0);
    EXPECT_EQ(chain.position()[0], 10.0);
    EXPECT_EQ(chain.position()[1], 10.0);
    bool saw_line_12 = false;
    for (const auto& s : chain.statuses) saw_line_12 = saw_line_12 || s.current_line == 12;
    EXPECT_TRUE(saw_line_12);
    for (std::size_t i = 1; i < chain.states.size(); ++i) ASSERT_EQ(chain.states[i].seq, chain.states[i - 1].seq + 1);
}

// The component takes the last block from the stream, and the bridge reads its pins before the
// component has written them (queue-depth 0, idle) and the stream after (empty). That status
// must not say "idle, nothing queued": a host would take the program as done (issue: the
// diamond ended 34.5 mm short under LinuxCNC). The take is made here by a second reader.
TEST(Bridge, BlocksTakenButNotYetInThePinsStillCount) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.run(400);
    ASSERT_EQ(chain.status().state, firtp_lcm::status_t::IDLE);
    ASSERT_EQ(chain.status().queue_depth, 0);
    chain.publish(block_message(10, 10, 5, 2, 12));
    while (chain.lcm->handleTimeout(0) > 0) {
    }
    const int taker = hal_init("taker");
    ASSERT_GT(taker, 0);
    hal_stream_t stream;
    ASSERT_EQ(hal_stream_attach(&stream, taker, stream::default_block_key, stream::block_types), 0);
    hal_stream_data record[stream::block_elements];
    ASSERT_EQ(hal_stream_read(&stream, record, nullptr), 0);  // the component's take, its pins not yet set
    EXPECT_EQ(hal_stream_depth(&stream), 0);
    const std::size_t before = chain.statuses.size();
    chain.control(1.0, false, false);  // a control makes a status due at once
    while (chain.lcm->handleTimeout(0) > 0) {
    }
    chain.chain->poll();
    while (chain.lcm->handleTimeout(0) > 0) {
    }
    ASSERT_EQ(chain.statuses.size(), before + 1);
    EXPECT_EQ(chain.status().state, firtp_lcm::status_t::IDLE);
    EXPECT_EQ(chain.status().queue_depth, 1);
    EXPECT_FALSE(chain.chain->bridge().idle());
    hal_stream_detach(&stream);
    hal_exit(taker);
}

TEST(Bridge, NanBlockIsRefusedNamingSeqAndLineAndStopsTheProgram) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(20, 0, 5, 1, 11));
    firtp_lcm::block_t bad = block_message(20, 20, 5, 2, 12);
    bad.target[1] = std::numeric_limits<double>::quiet_NaN();
    chain.run(50);
    chain.publish(bad);
    chain.publish(block_message(0, 20, 5, 3, 13));
    chain.run(600);
    const firtp_lcm::status_t& s = chain.status();
    EXPECT_EQ(s.state, firtp_lcm::status_t::ERROR);
    bool named = false;
    for (const auto& st : chain.statuses)
        named = named || (st.error_code == firtp_lcm::status_t::ERROR_BAD_VALUE &&
                          st.error_text.find("seq 2") != std::string::npos &&
                          st.error_text.find("line 12") != std::string::npos);
    EXPECT_TRUE(named) << chain.statuses.back().error_text;
    EXPECT_EQ(s.next_seq, 2);  // seq 2 and 3 were never accepted
    EXPECT_LT(chain.position()[0], 20.0);   // stopped on the path of seq 1
    EXPECT_EQ(chain.position()[1], 0.0);
    EXPECT_TRUE(std::isfinite(chain.position()[0]));
}

TEST(Bridge, GapIsReportedAndTheResentBlockRunsOnce) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.publish(block_message(0, 0, 5, 3, 13));  // seq 2 lost on the way
    chain.run(20);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_SEQUENCE_GAP);
    EXPECT_NE(chain.status().error_text.find("expected seq 2"), std::string::npos);
    EXPECT_EQ(chain.status().next_seq, 2);
    chain.publish(block_message(10, 10, 5, 2, 12));  // go-back-N: 2, then 3
    chain.publish(block_message(0, 0, 5, 3, 13));
    chain.publish(block_message(10, 10, 5, 2, 12));  // a late duplicate of 2
    chain.run(600);
    EXPECT_EQ(chain.status().next_seq, 4);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_REPEATED);
    EXPECT_EQ(chain.position()[0], 0.0);  // ended at seq 3's target: 2 did not run again after it
    EXPECT_EQ(chain.position()[1], 0.0);
    EXPECT_EQ(chain.status().rejected, 2);
}

TEST(Bridge, LateCopyOfAnEarlierProgramNeverRunsAgain) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(10, 0, 5, 1, 11));
    chain.run(300);
    chain.publish(block_message(0, 10, 6, 1, 21));
    chain.run(300);
    chain.publish(block_message(10, 0, 5, 1, 11));  // delayed duplicate from program 5
    chain.run(300);
    EXPECT_EQ(chain.position()[0], 0.0);
    EXPECT_EQ(chain.position()[1], 10.0);
    EXPECT_EQ(chain.status().program, 6);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_REPEATED);
}

TEST(Bridge, ControlOfANewHostSessionTakesEffectAndOldMessagesDoNot) {
    test::Chain chain(test::message_machine());
    chain.control(0.5, false, false, 1);
    chain.control(0.5, false, false, 1);
    chain.run(2);
    EXPECT_EQ(chain.status().feed_scale, 0.5);
    chain.control(1.0, false, false, 2);  // a new host: its seq restarts
    chain.control_seq = 0;
    chain.control(1.0, false, false, 2);
    chain.run(2);
    EXPECT_EQ(chain.status().feed_scale, 1.0);
    firtp_lcm::control_t stale{};
    stale.session = 2;
    stale.seq = 1;
    stale.feed_scale = 0.1;
    messages::publish(*chain.lcm, messages::control_channel, stale);
    chain.run(2);
    EXPECT_EQ(chain.status().feed_scale, 1.0);
}

TEST(Bridge, HoldStopsOnThePathAndResumes) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(30, 0, 5, 1, 11));
    chain.run(100);
    chain.control(1.0, true, false);
    chain.run(300);
    EXPECT_EQ(chain.status().state, firtp_lcm::status_t::HOLDING);
    const double held = chain.position()[0];
    EXPECT_GT(held, 0.0);
    EXPECT_LT(held, 30.0);
    chain.run(50);
    EXPECT_EQ(chain.position()[0], held);
    chain.control(1.0, false, false);
    chain.run(800);
    EXPECT_EQ(chain.position()[0], 30.0);
}

TEST(Bridge, AbortDropsTheQueueAndANewProgramStartsFromThere) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(30, 0, 5, 1, 11));
    chain.publish(block_message(30, 30, 5, 2, 12));
    chain.run(100);
    chain.control(1.0, false, true);
    chain.run(400);
    EXPECT_EQ(chain.status().queue_depth, 0);
    const double stopped = chain.position()[0];
    EXPECT_LT(stopped, 30.0);
    chain.publish(block_message(30, 30, 5, 3, 13));  // the rest of the aborted program: refused
    chain.run(10);
    EXPECT_EQ(chain.position()[0], stopped);
    chain.control(1.0, false, false);
    chain.publish(block_message(0, 0, 7, 1, 31));
    chain.run(600);
    EXPECT_EQ(chain.position()[0], 0.0);
    EXPECT_EQ(chain.position()[1], 0.0);
}

namespace {

// A sealed block damaged in transit: its X target's lowest exponent bit flipped (10 -> 20), type
// hash and length intact, so it still decodes as a valid block.
std::vector<std::uint8_t> damaged_block(firtp_lcm::block_t block) {
    std::vector<std::uint8_t> bytes = messages::seal_encoded(block);
    constexpr std::size_t target_x = 8 + 8 + 8 + 8 + 4 + 1 + 1;
    bytes[target_x + 1] ^= 0x10;
    return bytes;
}

std::string crc_text(const std::vector<std::uint8_t>& bytes) {
    const std::size_t n = bytes.size();
    const std::uint32_t sent = std::uint32_t{bytes[n - 4]} << 24 | std::uint32_t{bytes[n - 3]} << 16 |
                               std::uint32_t{bytes[n - 2]} << 8 | bytes[n - 1];
    char text[80];
    std::snprintf(text, sizeof text, "(crc 0x%08x, computed 0x%08x)", sent, messages::crc32(bytes.data(), n - 4));
    return text;
}

}  // namespace

// A block whose bytes were damaged on the way (it still decodes, as a block to X 20 instead of
// 10) is refused before anything else, reported naming it and the crc, and not accepted: next_seq
// stays, so the block after it is a gap, exactly as if it had been lost; the resent block runs,
// once, to its real target.
TEST(Bridge, CorruptedBlockIsRefusedLikeALostOneAndTheResendRunsOnce) {
    test::Chain chain(test::message_machine());
    chain.publish(block_message(10, 0, 5, 1, 11));
    const std::vector<std::uint8_t> damaged = damaged_block(block_message(10, 10, 5, 2, 12));
    {
        firtp_lcm::block_t as_decoded;
        ASSERT_EQ(as_decoded.decode(damaged.data(), 0, static_cast<int>(damaged.size())), static_cast<int>(damaged.size()));
        ASSERT_EQ(as_decoded.target[0], 20.0);
        ASSERT_FALSE(messages::validate(as_decoded));  // to LCM and validate() a good block
    }
    chain.publish_bytes(messages::block_channel, damaged);
    chain.run(2);
    const firtp_lcm::status_t refused = chain.status();
    EXPECT_EQ(refused.error_code, firtp_lcm::status_t::ERROR_CORRUPTED);
    EXPECT_EQ(refused.error_text,
              "block seq 2 (line 12): corrupted: CRC mismatch " + crc_text(damaged) + "; refused, expected seq 2");
    EXPECT_EQ(refused.next_seq, 2);  // not accepted
    EXPECT_EQ(refused.rejected, 1);
    EXPECT_EQ(refused.corrupted, 1);
    EXPECT_NE(refused.state, firtp_lcm::status_t::ERROR);  // not a fault: the resend repairs it
    chain.publish(block_message(0, 10, 5, 3, 13));
    chain.run(2);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_SEQUENCE_GAP);  // as after a lost block
    EXPECT_EQ(chain.status().next_seq, 2);
    chain.publish(block_message(10, 10, 5, 2, 12));  // the resend
    chain.publish(block_message(0, 10, 5, 3, 13));
    chain.run(800);
    EXPECT_EQ(chain.status().next_seq, 4);
    EXPECT_EQ(chain.chain->bridge().blocks_forwarded(), 3);
    EXPECT_EQ(chain.chain->bridge().messages_corrupted(), 1);
    EXPECT_EQ(chain.position()[0], 0.0);
    EXPECT_EQ(chain.position()[1], 10.0);
    double max_x = 0.0;  // the damaged target (X 20) never ran
    for (const auto& s : chain.states) max_x = std::max(max_x, s.position[0]);
    EXPECT_LE(max_x, 10.0 + 1e-9);
}

// A control damaged on the way (feed override 0.5 -> 1.0 by one bit) is ignored, the override in
// effect stays, and it is reported; the next intact one takes effect.
TEST(Bridge, CorruptedControlIsIgnoredAndReported) {
    test::Chain chain(test::message_machine());
    firtp_lcm::control_t c{};
    c.session = 1;
    c.seq = 1;
    c.feed_scale = 0.5;
    std::vector<std::uint8_t> bytes = messages::seal_encoded(c);
    constexpr std::size_t feed_scale = 8 + 8 + 8 + 8;
    bytes[feed_scale + 1] ^= 0x10;  // 0x3FE0... -> 0x3FF0...: 1.0
    chain.publish_bytes(messages::control_channel, bytes);
    chain.run(2);
    EXPECT_EQ(chain.status().feed_scale, 1.0);
    EXPECT_EQ(chain.status().error_code, firtp_lcm::status_t::ERROR_CORRUPTED);
    EXPECT_EQ(chain.status().error_text,
              "control seq 1: corrupted: CRC mismatch " + crc_text(bytes) + "; ignored, the controls in effect stay");
    EXPECT_EQ(chain.status().corrupted, 1);
    EXPECT_EQ(chain.status().rejected, 0);  // not a block
    chain.control(0.25, false, false);
    chain.run(2);
    EXPECT_EQ(chain.status().feed_scale, 0.25);
}

// Every axis state names the control whose levels its period applied (axis_state_t control_session,
// control_seq; what `firtp replay` places the controls by): none at first; of two taken before one
// period, the later; a new session's own count; an older message ignored, not named.
TEST(Bridge, EveryAxisStateNamesTheControlAppliedInItsPeriod) {
    test::Chain chain(test::message_machine());
    chain.run(2);
    EXPECT_EQ(chain.states.back().control_session, 0);
    EXPECT_EQ(chain.states.back().control_seq, 0);
    chain.control(0.5, false, false);  // session 1 seq 1, superseded before a period reads it
    chain.control(0.6, true, false);   // seq 2
    chain.run(1);
    EXPECT_EQ(chain.states.back().control_session, 1);
    EXPECT_EQ(chain.states.back().control_seq, 2);
    chain.run(3);
    EXPECT_EQ(chain.states.back().control_seq, 2);
    EXPECT_EQ(chain.status().feed_scale, 0.6);
    chain.control(0.7, false, false, 9);  // a new host: session 9, seq 3 (the fixture counts on)
    chain.run(1);
    EXPECT_EQ(chain.states.back().control_session, 9);
    EXPECT_EQ(chain.states.back().control_seq, 3);
    firtp_lcm::control_t older{};
    older.session = 9;
    older.seq = 2;
    older.feed_scale = 0.1;
    messages::publish(*chain.lcm, messages::control_channel, older);
    chain.run(2);
    EXPECT_EQ(chain.states.back().control_seq, 3);
    EXPECT_EQ(chain.status().feed_scale, 0.7);
}

// The pins' sequence lock (control_pins.hpp): the reader takes the levels only as one whole
// generation; while the writer is between its two generation stores it keeps the last ones.
TEST(ControlPins, TheReaderTakesOnlyWholeGenerations) {
    hal_u32_t gen = 0;
    hal_float_t feed = 1.0;
    hal_bit_t hold = false, abort = false;
    const control_pins::Pins pins{&gen, &feed, &hold, &abort};
    control_pins::Levels levels{0.9, false, false};
    std::uint32_t applied = 7;
    ASSERT_TRUE(control_pins::read(pins, levels, applied));  // unconnected: 0, taken as they are
    EXPECT_EQ(applied, 0u);
    EXPECT_EQ(levels.feed_scale, 1.0);
    EXPECT_EQ(control_pins::write(pins, 0, {0.5, true, false}), 2u);
    ASSERT_TRUE(control_pins::read(pins, levels, applied));
    EXPECT_EQ(applied, 2u);
    EXPECT_EQ(levels.feed_scale, 0.5);
    EXPECT_TRUE(levels.hold);
    gen = 3;  // the writer has begun generation 4: feed written, hold not yet
    feed = 0.25;
    EXPECT_FALSE(control_pins::read(pins, levels, applied));
    EXPECT_EQ(applied, 2u);
    EXPECT_EQ(levels.feed_scale, 0.5);
    gen = 4;
    ASSERT_TRUE(control_pins::read(pins, levels, applied));
    EXPECT_EQ(applied, 4u);
    EXPECT_EQ(levels.feed_scale, 0.25);
}

namespace {

// Five blocks from the real host through a relay that damages the first copy of block `damaged_seq`
// (its X target 10 -> 20: a bit flip that leaves a valid block); statuses and axis states back.
struct HostRun {
    test::Chain chain{test::message_machine()};
    int copies = 0;  // of the damaged seq that passed the relay
    host::Result result = host::Result::running;
    host::Statistics statistics;
    std::string error;
    std::int64_t periods = 0;

    explicit HostRun(std::int64_t damaged_seq) {
        auto host_lcm = messages::open("memq://");
        struct Relay {
            HostRun* run;
            lcm::LCM* to_host;
            std::int64_t seq;
            void down(const lcm::ReceiveBuffer* b, const std::string& channel) {
                const auto* data = static_cast<const std::uint8_t*>(b->data);
                std::vector<std::uint8_t> bytes(data, data + b->data_size);
                const auto r = messages::receive<firtp_lcm::block_t>(bytes.data(), bytes.size());
                if (channel == messages::block_channel && r.decoded && r.message.seq == seq && run->copies++ == 0)
                    bytes[8 + 8 + 8 + 8 + 4 + 1 + 1 + 1] ^= 0x10;
                run->chain.publish_bytes(channel.c_str(), bytes);
            }
            void up(const lcm::ReceiveBuffer* b, const std::string& channel) {
                to_host->publish(channel, b->data, b->data_size);
            }
        } relay{this, host_lcm.get(), damaged_seq};
        auto* down = host_lcm->subscribe("FIRTP_BLOCK|FIRTP_CONTROL", &Relay::down, &relay);
        auto* up = chain.lcm->subscribe("FIRTP_STATUS|FIRTP_AXIS_STATE", &Relay::up, &relay);
        messages::keep_everything(down);
        messages::keep_everything(up);

        Program program;
        program.file = "corrupted.ngc";
        for (int i = 1; i <= 5; ++i) {
            Block b;
            b.target[0] = i % 2 == 0 ? 10.0 : 0.0;  // seq 2 and 4 to X 10, their damaged copies to X 20
            b.target[1] = 5.0 * i;
            b.feed = 100.0;
            b.tolerance = 0.05;
            b.line = 10 + i;
            program.blocks.push_back(b);
        }
        host::HostOptions options;
        options.program_id = 9;
        options.clock = [this] { return host::Clock::time_point(std::chrono::milliseconds(periods)); };
        host::Host host(*host_lcm, program, options);
        for (; periods < 20000 && host.result() == host::Result::running; ++periods) {
            host.step();
            chain.run(1);
            while (host_lcm->handleTimeout(0) > 0) {
            }
        }
        result = host.result();
        statistics = host.statistics();
        error = host.error();
        chain.lcm->unsubscribe(up);
    }
    double max_abs_x() const {
        double x = 0.0;
        for (const auto& s : chain.states) x = std::max(x, std::abs(s.position[0]));
        return x;
    }
    // The first period whose status shows `pred`, or -1.
    template <class Pred> std::int64_t first_status(Pred pred) const {
        for (const auto& s : chain.statuses)
            if (pred(s)) return s.tick;
        return -1;
    }
};

}  // namespace

// The real host's first copy of seq 2 is damaged on the way. The bridge refuses it (counted; its
// report is then hidden behind the gaps of 3-5, as a lost block's would be), the host goes back
// and resends: every block runs once, the damaged target never.
TEST(Bridge, HostResendsACorruptedBlockOnceAndTheProgramCompletes) {
    const HostRun run(2);
    ASSERT_EQ(run.result, host::Result::done) << run.error;
    EXPECT_EQ(run.copies, 2);  // the damaged copy and one resend
    EXPECT_EQ(run.chain.chain->bridge().blocks_forwarded(), 5);
    EXPECT_EQ(run.chain.chain->bridge().messages_corrupted(), 1);
    EXPECT_EQ(run.chain.status().corrupted, 1);
    EXPECT_EQ(run.chain.status().next_seq, 6);
    EXPECT_EQ(run.statistics.corrupted_refused, 1);
    EXPECT_EQ(run.statistics.go_backs, 1);
    EXPECT_LE(run.max_abs_x(), 10.0 + 1e-9);  // X 20 never ran
    EXPECT_EQ(run.chain.position()[0], 0.0);
    EXPECT_EQ(run.chain.position()[1], 25.0);
    std::printf("corrupted seq 2 through the host: %lld published for 5 (%lld go-backs), refused %lld, corrupted %lld\n",
                static_cast<long long>(run.statistics.blocks_published), static_cast<long long>(run.statistics.go_backs),
                static_cast<long long>(run.statistics.rejected), static_cast<long long>(run.statistics.corrupted_refused));
}

// The last block damaged: nothing hides the report, which names it; the host goes back at the
// refusal (ERROR_CORRUPTED), not after its 500 ms resend timeout as for a lost last block.
TEST(Bridge, CorruptedLastBlockIsNamedAndResentAtOnce) {
    const HostRun run(5);
    ASSERT_EQ(run.result, host::Result::done) << run.error;
    EXPECT_EQ(run.copies, 2);
    EXPECT_EQ(run.chain.chain->bridge().blocks_forwarded(), 5);
    EXPECT_EQ(run.statistics.corrupted_refused, 1);
    EXPECT_EQ(run.statistics.go_backs, 1);
    const std::int64_t refused = run.first_status([](const firtp_lcm::status_t& s) {
        return s.error_code == firtp_lcm::status_t::ERROR_CORRUPTED &&
               s.error_text.find("block seq 5 (line 15): corrupted: CRC mismatch (crc 0x") == 0 &&
               s.error_text.find("; refused, expected seq 5") != std::string::npos;
    });
    const std::int64_t accepted = run.first_status([](const firtp_lcm::status_t& s) { return s.next_seq == 6; });
    ASSERT_GE(refused, 0);
    ASSERT_GT(accepted, refused);
    EXPECT_LT(accepted - refused, 20);  // periods (ms): at once, not after the 500 ms timeout
    EXPECT_LE(run.max_abs_x(), 10.0 + 1e-9);
    EXPECT_EQ(run.chain.position()[1], 25.0);
    std::printf("corrupted last block through the host: refused at period %lld, its resend accepted at %lld\n",
                static_cast<long long>(refused), static_cast<long long>(accepted));
}

// firtp-lcm-bridge unloaded and loaded again while firtp.so runs a program (a LinuxCNC user's
// halcmd unload, then lcm.hal again): the new bridge takes the program over once every block the
// old one wrote is taken (until then it says nothing, and refuses the host's next block for a
// resend), and the control generation in effect (named 0, 0, without an error). The program
// finishes, every block once; the states go on tick by tick, their seq from 1. Restarted within a
// period (nothing waiting in the state stream: the program in the first period tells) or after 5.
class BridgeRestart : public testing::TestWithParam<int> {};

TEST_P(BridgeRestart, TheNewBridgeTakesTheProgramAndTheControlOver) {
    test::Chain chain(test::message_machine());
    chain.control(0.8, false, false);  // session 1 seq 1: the first bridge's generation 2
    const int written = 2 * defaults::max_blocks + 8;
    for (int seq = 1; seq <= written; ++seq) chain.publish(block_message(seq % 2, 0.01 * seq, 5, seq, seq));
    chain.run(1);
    ASSERT_LT(chain.states.back().next_seq, written);  // blocks left in the stream
    EXPECT_EQ(chain.states.back().control_seq, 1);
    const std::size_t states_before = chain.states.size(), statuses_before = chain.statuses.size();

    chain.chain->restart_bridge(GetParam());  // firtp.so alone for 0 or 5 periods
    chain.publish(block_message(0, 0.01 * (written + 1), 5, written + 1, written + 1));  // the host's next
    chain.run(1);
    EXPECT_EQ(chain.statuses.size(), statuses_before);  // taking over: nothing said yet
    chain.run(10);
    ASSERT_GT(chain.statuses.size(), statuses_before);
    EXPECT_EQ(chain.status().program, 5);
    EXPECT_EQ(chain.status().next_seq, written + 1);  // every block the old bridge wrote, taken
    bool refused_for_resend = false;
    for (std::size_t i = statuses_before; i < chain.statuses.size(); ++i) {
        const firtp_lcm::status_t& s = chain.statuses[i];
        EXPECT_NE(s.error_code, firtp_lcm::status_t::ERROR_LOST_STATE) << s.error_text;
        // Periods waiting: refused for a resend; none (restarted within a period): as a gap, not
        // knowing the program yet. Either way the host resends it.
        const std::int32_t refusal = GetParam() > 0 ? std::int32_t{firtp_lcm::status_t::ERROR_QUEUE_FULL}
                                                    : std::int32_t{firtp_lcm::status_t::ERROR_SEQUENCE_GAP};
        refused_for_resend = refused_for_resend ||
                             (s.error_code == refusal && s.error_text.find("seq " + std::to_string(written + 1)) != std::string::npos);
    }
    EXPECT_TRUE(refused_for_resend);
    ASSERT_GT(chain.states.size(), states_before);
    EXPECT_EQ(chain.states[states_before].seq, 1);
    EXPECT_EQ(chain.states[states_before].tick, chain.states[states_before - 1].tick + 1);
    EXPECT_EQ(chain.states[states_before].control_seq, 0);  // the old bridge's control: not this one's

    chain.publish(block_message(0, 0.01 * (written + 1), 5, written + 1, written + 1));  // resent
    chain.control(1.0, false, false);  // seq 2, the new bridge's first generation
    for (int k = 0; k < 100 && !(chain.status().next_seq == written + 2 &&
                                 chain.status().state == firtp_lcm::status_t::IDLE); ++k)
        chain.run(500);
    EXPECT_EQ(chain.status().state, firtp_lcm::status_t::IDLE);
    EXPECT_EQ(chain.status().next_seq, written + 2);
    EXPECT_EQ(chain.states.back().control_session, 1);
    EXPECT_EQ(chain.states.back().control_seq, 2);
    EXPECT_EQ(chain.position()[1], 0.01 * (written + 1));
    for (std::size_t i = states_before + 1; i < chain.states.size(); ++i)
        ASSERT_EQ(chain.states[i].tick, chain.states[i - 1].tick + 1);
}

INSTANTIATE_TEST_SUITE_P(Bridge, BridgeRestart, testing::Values(0, 5));

// The servo thread stalls while the new bridge starts (LinuxCNC under load: "USRMOT: ERROR:
// command timeout"): the host's next block comes and the bridge polls before any period has been
// read. It must not say program 0 then: a host whose program runs on takes a status naming
// another program for a second as the component's restart, and gives its program up (the
// linuxcnc_bridge restart test failed so, once in 52 runs on a loaded machine). Nothing is
// said until a period names the program; then the takeover goes on as above.
TEST(BridgeRestart, SaysNoProgramBeforeItHasReadAPeriod) {
    test::Chain chain(test::message_machine());
    const int written = 2 * defaults::max_blocks + 8;
    for (int seq = 1; seq <= written; ++seq) chain.publish(block_message(seq % 2, 0.01 * seq, 5, seq, seq));
    chain.run(1);
    const std::size_t statuses_before = chain.statuses.size();

    chain.chain->restart_bridge(0);
    chain.publish(block_message(0, 0.01 * (written + 1), 5, written + 1, written + 1));
    for (int k = 0; k < 50; ++k) {  // the bridge's loop runs; the servo thread does not
        while (chain.lcm->handleTimeout(0) > 0) {
        }
        chain.chain->poll();
    }
    while (chain.lcm->handleTimeout(0) > 0) {
    }
    for (std::size_t i = statuses_before; i < chain.statuses.size(); ++i)
        EXPECT_EQ(chain.statuses[i].program, 5) << "status " << chain.statuses[i].seq << " before any period";

    chain.run(20);  // the servo thread runs again
    ASSERT_GT(chain.statuses.size(), statuses_before);
    EXPECT_EQ(chain.status().program, 5);
    for (std::size_t i = statuses_before; i < chain.statuses.size(); ++i) EXPECT_EQ(chain.statuses[i].program, 5);
}

// The host's control (republished every 100 ms) reaches the new bridge before lcm.hal has netted
// its pins and before it has read a period. Taken then, the bridge took its own unnetted pin's 0 for
// the generation in effect, while the periods waiting name the old bridge's, and it reported "the
// component applied control generation 4, which this bridge did not write" (ERROR_LOST_STATE): the
// host gave the program up (the linuxcnc_bridge restart test, once in 18 runs under load). The
// control now waits for the first period, which names the generation in effect.
TEST(BridgeRestart, AControlBeforeThePinsAreNettedWaitsForAPeriod) {
    test::Chain chain(test::message_machine());
    chain.control(0.8, false, false);
    chain.control(0.9, false, false);  // the first bridge's generation 4
    for (int seq = 1; seq <= 8; ++seq) chain.publish(block_message(seq % 2, 0.01 * seq, 5, seq, seq));
    chain.run(3);
    ASSERT_EQ(chain.states.back().control_seq, 2);
    const std::size_t states_before = chain.states.size(), statuses_before = chain.statuses.size();

    chain.chain->restart_bridge(5, false);  // firtp.so runs on alone: 5 periods wait, naming generation 4
    chain.control(1.0, false, false);       // seq 3, taken before those periods are read and before the nets
    for (int k = 0; k < 5; ++k) {
        while (chain.lcm->handleTimeout(0) > 0) {
        }
        chain.chain->poll();
    }
    chain.chain->net_bridge();
    for (int k = 0; k < 200 && !(chain.statuses.size() > statuses_before && chain.status().state == firtp_lcm::status_t::IDLE); ++k)
        chain.run(10);
    ASSERT_GT(chain.statuses.size(), statuses_before);
    for (std::size_t i = statuses_before; i < chain.statuses.size(); ++i)
        EXPECT_NE(chain.statuses[i].error_code, firtp_lcm::status_t::ERROR_LOST_STATE) << chain.statuses[i].error_text;
    ASSERT_GT(chain.states.size(), states_before);
    EXPECT_EQ(chain.states.back().control_session, 1);
    EXPECT_EQ(chain.states.back().control_seq, 3);  // the waiting control, applied and named
    EXPECT_EQ(chain.status().next_seq, 9);
    EXPECT_EQ(chain.position()[1], 0.08);
}
