// Block delivery: order, exactly once, flow control, go-back-N after loss / reordering.
#include "test_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <memory>

namespace firtp::host::test {
namespace {

struct StreamTest : ::testing::Test {
    lcm::LCM lcm{"memq://"};
    FakeClock clock;
};

TEST_F(StreamTest, DeliversEveryBlockOnceInOrderWithinQueueFree) {
    FakeComponent component(lcm, 4);
    component.ticks_per_block = 5;
    const Program program = line_program(50, {7, 8});
    Host host(lcm, program, options_for(clock));
    component.tick();  // a status is waiting when the host starts sending
    EXPECT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(50));
    EXPECT_EQ(component.received, one_to(50));  // nothing sent twice
    EXPECT_EQ(component.rejected, 0);
    EXPECT_LE(component.max_depth, 4);
    EXPECT_EQ(component.window_violations, 0);
    EXPECT_EQ(component.accepted[6].target[0], component.accepted[5].target[0]);  // zero-length sent
    EXPECT_EQ(host.statistics().go_backs, 0);
    EXPECT_EQ(host.progress().executed, 50u);
}

// Hands a program's blocks over one at a time, counting them.
class CountingPuller : public SpanPuller {
public:
    CountingPuller(const std::vector<Block>& blocks, std::size_t& read) : SpanPuller(blocks), read_(read) {}
    bool next(Block& block) override {
        if (!SpanPuller::next(block)) return false;
        ++read_;
        return true;
    }

private:
    std::size_t& read_;
};

// The host reads every block once to check them all before sending, then again only as flow
// control lets them go: it never holds more than the component's window, not the program.
TEST_F(StreamTest, ReadsTheProgramOnlyAsFarAsTheComponentTakesIt) {
    FakeComponent component(lcm, 4);
    component.ticks_per_block = 5;
    const Program program = line_program(2000);
    std::deque<std::size_t> reads;  // blocks handed out, one counter a reader
    ProgramFeed feed;
    feed.blocks = program.blocks.size();
    feed.read = [&] {
        reads.push_back(0);
        return std::make_unique<CountingPuller>(program.blocks, reads.back());
    };
    Host host(lcm, feed, options_for(clock));
    ASSERT_EQ(reads.size(), 2u);
    EXPECT_EQ(reads[0], 2000u);  // checked
    EXPECT_EQ(reads[1], 0u);     // nothing sent yet
    component.tick();
    std::int64_t ahead = 0;  // read but not yet executed, at most
    EXPECT_EQ(run_loop(host, component, clock, 100000,
                       [&](int) { ahead = std::max(ahead, static_cast<std::int64_t>(reads[1]) - component.executed); }),
              Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(2000));
    EXPECT_EQ(reads[1], 2000u);
    EXPECT_EQ(reads.size(), 2u);
    EXPECT_LE(ahead, 2 * 4 + 1);  // the queue and what its free slots allow
    EXPECT_GE(ahead, 4);
}

TEST_F(StreamTest, SendsOnlyTheInitialWindowBeforeTheFirstStatus) {
    FakeComponent component(lcm, 100);
    component.silent = true;
    const Program program = line_program(100);
    Host host(lcm, program, options_for(clock));
    host.step();
    while (lcm.handleTimeout(0) > 0) {}
    EXPECT_EQ(component.received, one_to(16));
    component.silent = false;
    EXPECT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(100));
}

TEST_F(StreamTest, GoesBackAfterALostBlock) {
    FakeComponent component(lcm, 8);
    component.drop_once = {5};
    const Program program = line_program(30);
    Host host(lcm, program, options_for(clock));
    component.tick();
    int ticks = 0;
    EXPECT_EQ(run_loop(host, component, clock, 100000, [&](int t) { ticks = t; }), Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(30));
    EXPECT_GE(host.statistics().go_backs, 1);
    EXPECT_GT(component.gaps, 0);
    EXPECT_LT(ticks, 200);  // the gap status triggers the resend, not the 500 ms timeout
}

TEST_F(StreamTest, LostLastBlockIsResentAfterTheTimeout) {
    FakeComponent component(lcm, 8);
    component.drop_once = {6};
    const Program program = line_program(6);
    Host host(lcm, program, options_for(clock));
    component.tick();
    int ticks = 0;
    EXPECT_EQ(run_loop(host, component, clock, 100000, [&](int t) { ticks = t; }), Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(6));
    EXPECT_EQ(host.statistics().go_backs, 1);
    EXPECT_GE(ticks, 500);
}

TEST_F(StreamTest, DuplicatesAreHarmless) {
    FakeComponent component(lcm, 8);
    component.duplicate_once = {3, 7, 20};
    const Program program = line_program(20);
    Host host(lcm, program, options_for(clock));
    component.tick();
    EXPECT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(20));
    EXPECT_EQ(component.repeats, 3);
    EXPECT_EQ(component.executed, 20);
    EXPECT_EQ(host.statistics().go_backs, 0);
    EXPECT_EQ(host.statistics().rejected, 3);
}

TEST_F(StreamTest, ReorderingIsRecovered) {
    FakeComponent component(lcm, 8);
    component.delay_once = {4, 12};
    const Program program = line_program(25);
    Host host(lcm, program, options_for(clock));
    component.tick();
    EXPECT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(25));
    EXPECT_EQ(component.executed, 25);
    EXPECT_GE(host.statistics().go_backs, 1);
}

TEST_F(StreamTest, LossesEverywhereStillDeliverInOrder) {
    FakeComponent component(lcm, 6);
    for (std::int64_t seq = 3; seq <= 200; seq += 7) component.drop_once.insert(seq);
    for (std::int64_t seq = 5; seq <= 200; seq += 11) component.duplicate_once.insert(seq);
    for (std::int64_t seq = 9; seq <= 200; seq += 13) component.delay_once.insert(seq);
    const Program program = line_program(200);
    Host host(lcm, program, options_for(clock));
    component.tick();
    EXPECT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_EQ(seqs(component.accepted), one_to(200));
    EXPECT_EQ(component.executed, 200);
    EXPECT_EQ(component.window_violations, 0);
    EXPECT_EQ(component.queue_full, 0);
}

TEST_F(StreamTest, WaitsForAnotherProgramToFinish) {
    FakeComponent component(lcm, 8);
    component.ticks_per_block = 20;
    component.preload(7, 5);
    const Program program = line_program(10);
    Host host(lcm, program, options_for(clock));
    component.tick();
    EXPECT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_EQ(component.rejected, 0);
    EXPECT_EQ(seqs(component.accepted), one_to(10));
    EXPECT_EQ(component.program, host.program_id());
}

TEST_F(StreamTest, BlockNeverAcceptedFails) {
    FakeComponent component(lcm, 8);
    component.refuse_always = FakeComponent::Refusal{5, firtp_lcm::status_t::ERROR_QUEUE_FULL, "queue full"};
    const Program program = line_program(10);
    Host host(lcm, program, options_for(clock));
    component.tick();
    EXPECT_EQ(run_loop(host, component, clock), Result::failed);
    EXPECT_THAT(host.error(), ::testing::Eq("block seq 5 (line 50) not accepted after 10 resends; component: queue full"));
    EXPECT_EQ(seqs(component.accepted), one_to(4));
}

}  // namespace
}  // namespace firtp::host::test
