// How a program ends: done, failed (with the component's text), lost, aborted.
#include "test_support.hpp"

#include <firtp/host_report.hpp>
#include <firtp/messages.hpp>
#include <firtp_lcm/status_t.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace firtp::host::test {
namespace {

using firtp_lcm::status_t;
using ::testing::HasSubstr;

struct OutcomeTest : ::testing::Test {
    lcm::LCM lcm{"memq://"};
    FakeClock clock;
};

TEST_F(OutcomeTest, DoneOnlyOnceEveryBlockHasExecuted) {
    FakeComponent component(lcm, 32);
    component.ticks_per_block = 10;
    const Program program = line_program(12);
    Host host(lcm, program, options_for(clock));
    component.tick();
    bool saw_all_acknowledged_while_running = false;
    const Result result = run_loop(host, component, clock, 100000, [&](int) {
        const Progress p = host.progress();
        if (p.acknowledged == 12 && host.result() == Result::running) saw_all_acknowledged_while_running = true;
    });
    EXPECT_EQ(result, Result::done);
    EXPECT_TRUE(saw_all_acknowledged_while_running);
    EXPECT_EQ(component.executed, 12);
    EXPECT_EQ(component.depth(), 0);
    EXPECT_TRUE(host.error().empty());
}

// A bridge that reads the component's pins one at a time (firtp-lcm-bridge without its axis-state
// stream, or of an older build): between two reads the component can take the last blocks from
// its stream and not yet say so, and one status then reads idle, nothing queued, every block
// sent. The program is not over until a status of a later period says so too
// (linuxcnc_bridge.firtp_config_host_diamond: LinuxCNC ended 0.2 s into the 0.8 s diamond).
TEST_F(OutcomeTest, OneIdleStatusWithBlocksStillQueuedDoesNotEndTheProgram) {
    FakeComponent component(lcm, 32);
    component.ticks_per_block = 10;
    const Program program = line_program(6);
    Host host(lcm, program, options_for(clock));
    component.tick();
    bool torn = false, ended_early = false;
    const Result result = run_loop(host, component, clock, 100000, [&](int) {
        if (!torn && host.progress().acknowledged == 6 && component.depth() > 2) component.torn_next = torn = true;
        if (host.result() != Result::running && component.depth() > 0) ended_early = true;
    });
    EXPECT_TRUE(torn);
    EXPECT_FALSE(ended_early);
    EXPECT_EQ(result, Result::done);
    EXPECT_EQ(component.executed, 6);
}

TEST_F(OutcomeTest, EmptyProgramIsDoneAtOnce) {
    FakeComponent component(lcm);
    const Program program = line_program(0);
    Host host(lcm, program, options_for(clock));
    EXPECT_EQ(host.step(), Result::done);
}

TEST_F(OutcomeTest, InvalidBlockFailsBeforeAnythingIsSent) {
    FakeComponent component(lcm);
    Program program = line_program(5);
    program.blocks[2].feed = std::nan("");
    Host host(lcm, program, options_for(clock));
    EXPECT_EQ(run_loop(host, component, clock), Result::failed);
    EXPECT_THAT(host.error(), HasSubstr("seq 3"));
    EXPECT_TRUE(component.received.empty());
}

TEST_F(OutcomeTest, ErrorStateFailsWithItsText) {
    FakeComponent component(lcm, 8);
    component.ticks_per_block = 10;
    const Program program = line_program(40);
    Host host(lcm, program, options_for(clock));
    component.tick();
    const Result result = run_loop(host, component, clock, 100000, [&](int tick) {
        if (tick == 50) component.fail("following error on X");
    });
    EXPECT_EQ(result, Result::failed);
    EXPECT_EQ(host.error(), "following error on X");
}

// Corrupt FIRTP_STATUS messages between the component's good ones: dropped, and the program runs
// to its end. A string length of 0 in an intact (sealed) message, which lcm-gen 1.3.1's decode
// threw on (before lcm-types/fix_string_decode.cmake the first one terminated the host; found by
// fuzz_lcm); noise; and a status whose next_seq and queue_free were damaged in transit (a bit flip
// each, the crc not matching): the host must not trust them (it would send beyond the window).
TEST_F(OutcomeTest, CorruptStatusMessagesAreDroppedNotFatal) {
    FakeComponent component(lcm, 8);
    const Program program = line_program(6);
    Host host(lcm, program, options_for(clock));
    component.tick();
    status_t corrupt{};
    corrupt.program = 1000;
    corrupt.error_text = "x";
    std::vector<unsigned char> bytes = firtp::messages::seal_encoded(corrupt);
    constexpr std::size_t length_at = 8 + 5 * 8 + 3 * 4 + 1 + 8 + 4;  // error_text's length
    for (int i = 0; i < 4; ++i) bytes[length_at + i] = 0;
    const std::uint32_t crc = firtp::messages::crc32(bytes.data(), bytes.size() - 4);
    for (std::size_t i = 0; i < 4; ++i) bytes[bytes.size() - 4 + i] = static_cast<unsigned char>(crc >> (24 - 8 * i));
    ASSERT_TRUE(firtp::messages::intact(bytes.data(), bytes.size()));
    const std::vector<unsigned char> noise(40, 0x5a);
    status_t lying{};
    lying.program = 1000;
    lying.next_seq = 1;
    lying.queue_free = 8;
    std::vector<unsigned char> damaged = firtp::messages::seal_encoded(lying);
    constexpr std::size_t next_seq_low = 8 + 5 * 8 - 1, queue_free_high = 8 + 5 * 8 + 4;
    damaged[next_seq_low] ^= 0x04;     // next_seq 1 -> 5: blocks 1-4 as if accepted
    damaged[queue_free_high] ^= 0x01;  // queue_free 8 -> 2^24 + 8: a window without end
    const Result result = run_loop(host, component, clock, 100000, [&](int tick) {
        const char* channel = firtp::messages::status_channel;
        if (tick % 7 == 0) lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
        if (tick % 11 == 0) lcm.publish(channel, noise.data(), static_cast<unsigned>(noise.size()));
        if (tick % 5 == 0) lcm.publish(channel, damaged.data(), static_cast<unsigned>(damaged.size()));
    });
    EXPECT_EQ(result, Result::done) << host.error();
    EXPECT_EQ(seqs(component.accepted), one_to(6));
    EXPECT_EQ(component.window_violations, 0);
    const std::int64_t dropped = host.statistics().corrupted_dropped;
    EXPECT_GT(dropped, 3);
    EXPECT_THAT(host_report("test.ngc", host, result, 1.0, false),
                HasSubstr("  corrupted in transit (CRC mismatch): 0 blocks and controls refused by the component, " +
                          std::to_string(dropped) + " statuses and axis states dropped here\n"));
}

TEST_F(OutcomeTest, OneOffRefusalIsRepairedByTheResend) {
    FakeComponent component(lcm, 8);
    const Program program = line_program(10);
    Host host(lcm, program, options_for(clock));
    component.tick();
    component.refuse_next(status_t::ERROR_NOT_ENABLED, "block seq 1 (line 10): component not enabled");
    EXPECT_EQ(run_loop(host, component, clock), Result::done);  // 2..8 gaps hide it; the resend passes
    EXPECT_EQ(seqs(component.accepted), one_to(10));
}

TEST_F(OutcomeTest, RefusalHiddenBehindGapsIsFoundByTheResend) {
    FakeComponent component(lcm, 8);
    const Program program = line_program(10);
    Host host(lcm, program, options_for(clock));
    component.tick();
    component.refuse_always = FakeComponent::Refusal{3, status_t::ERROR_BAD_TYPE, "block seq 3 (line 30): bad type"};
    EXPECT_EQ(run_loop(host, component, clock), Result::failed);
    EXPECT_EQ(host.error(), "block seq 3 (line 30): bad type");
    EXPECT_EQ(host.statistics().go_backs, 1);
}

TEST_F(OutcomeTest, OldErrorOfAnEarlierProgramIsIgnored) {
    FakeComponent component(lcm, 8);
    component.refuse_next(status_t::ERROR_BAD_VALUE, "block seq 3 (line 7): feed is NaN");
    firtp_lcm::block_t stale{};
    stale.program = 5;
    stale.seq = 1;
    firtp::messages::publish(lcm, "FIRTP_BLOCK", stale);
    while (lcm.handleTimeout(0) > 0) {}
    const Program program = line_program(10);
    Host host(lcm, program, options_for(clock));
    component.tick();  // the first status shows error_code BAD_VALUE of program 5
    EXPECT_EQ(run_loop(host, component, clock), Result::done);
}

TEST_F(OutcomeTest, SilenceIsLostContact) {
    FakeComponent component(lcm, 8);
    component.ticks_per_block = 50;
    const Program program = line_program(40);
    HostOptions options = options_for(clock);
    options.status_timeout = 2s;
    Host host(lcm, program, options);
    component.tick();
    int last_tick = 0;
    const Result result = run_loop(host, component, clock, 100000, [&](int tick) {
        last_tick = tick;
        if (tick == 100) component.silent = true;
    });
    EXPECT_EQ(result, Result::lost);
    EXPECT_THAT(host.error(), HasSubstr("no status from the component for 2000 ms"));
    EXPECT_NEAR(last_tick, 2100, 3);
}

TEST_F(OutcomeTest, NoComponentAtAllIsLostContact) {
    const Program program = line_program(3);
    HostOptions options = options_for(clock);
    Host host(lcm, program, options);
    Result result = Result::running;
    for (int tick = 0; tick < 10000 && result == Result::running; ++tick) {
        result = host.step();
        clock.advance(1ms);
    }
    EXPECT_EQ(result, Result::lost);
}

TEST_F(OutcomeTest, AbortStopsSendingAndEndsAborted) {
    FakeComponent component(lcm, 4);
    component.ticks_per_block = 20;
    const Program program = line_program(50);
    Host host(lcm, program, options_for(clock));
    component.tick();
    std::size_t accepted_at_abort = 0;
    const Result result = run_loop(host, component, clock, 100000, [&](int tick) {
        if (tick == 100) {
            host.abort();
            accepted_at_abort = component.accepted.size();
        }
    });
    EXPECT_EQ(result, Result::aborted);
    EXPECT_EQ(component.depth(), 0);
    EXPECT_LT(component.executed, 50);
    EXPECT_LE(component.accepted.size(), accepted_at_abort + 4);  // only what was already in flight
    ASSERT_FALSE(component.controls.empty());
    EXPECT_FALSE(component.controls.back().abort);  // released once stopped, for the next program
    EXPECT_TRUE(std::any_of(component.controls.begin(), component.controls.end(),
                            [](const auto& c) { return c.abort; }));
    host.abort();  // harmless after the end
    EXPECT_EQ(host.step(), Result::aborted);
}

TEST_F(OutcomeTest, HoldKeepsTheProgramRunningUntilResumed) {
    FakeComponent component(lcm, 8);
    component.ticks_per_block = 5;
    const Program program = line_program(20);
    Host host(lcm, program, options_for(clock));
    component.tick();
    bool holding_seen = false;
    const Result result = run_loop(host, component, clock, 100000, [&](int tick) {
        if (tick == 20) host.hold(true);
        if (tick > 30 && tick < 2000) {
            EXPECT_EQ(host.result(), Result::running);
            holding_seen = holding_seen || host.progress().state == status_t::HOLDING;
        }
        if (tick == 2000) host.hold(false);
    });
    EXPECT_EQ(result, Result::done);
    EXPECT_TRUE(holding_seen);
    EXPECT_EQ(component.executed, 20);
}

TEST_F(OutcomeTest, RunReturnsLostWithTheRealClock) {
    const Program program = line_program(3);
    HostOptions options;
    options.status_timeout = 100ms;
    Host host(lcm, program, options);
    const auto start = Clock::now();
    EXPECT_EQ(host.run(), Result::lost);
    EXPECT_GE(Clock::now() - start, 100ms);
    EXPECT_LT(Clock::now() - start, 2s);
}

TEST_F(OutcomeTest, RunStopsAtTheDeadlineOrAStopRequest) {
    const Program program = line_program(3);
    Host host(lcm, program, HostOptions{});
    EXPECT_EQ(host.run({}, Clock::now() + 30ms), Result::running);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_EQ(host.run(stop.get_token()), Result::running);
}

}  // namespace
}  // namespace firtp::host::test
