// FIRTP_AXIS_STATE: every message recorded in order when asked, seq gaps reported.
#include "test_support.hpp"

#include <gtest/gtest.h>

namespace firtp::host::test {
namespace {

struct AxisStateTest : ::testing::Test {
    lcm::LCM lcm{"memq://"};
    FakeClock clock;
    FakeComponent component{lcm, 8};
    Program program = line_program(20);
};

TEST_F(AxisStateTest, RecordsEveryMessageInOrder) {
    HostOptions options = options_for(clock);
    options.record_axis_states = true;
    Host host(lcm, program, options);
    ASSERT_EQ(run_loop(host, component, clock), Result::done);
    const auto& states = host.axis_states();
    ASSERT_FALSE(states.empty());
    // The last tick's message may still be queued when the host sees the final status.
    EXPECT_GE(static_cast<std::int64_t>(states.size()), component.axis_published - 1);
    for (std::size_t i = 0; i < states.size(); ++i) EXPECT_EQ(states[i].seq, static_cast<std::int64_t>(i) + 1);
    EXPECT_EQ(host.statistics().axis_states, static_cast<std::int64_t>(states.size()));
    EXPECT_EQ(host.statistics().axis_states_lost, 0);
    EXPECT_EQ(host.axis_state_gap_text(), "");
}

TEST_F(AxisStateTest, NotRecordedUnlessAsked) {
    Host host(lcm, program, options_for(clock));
    ASSERT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_TRUE(host.axis_states().empty());
    EXPECT_GT(host.statistics().axis_states, 0);  // still counted and checked
}

TEST_F(AxisStateTest, GapsAreReported) {
    component.skip_axis_seq = 10;
    HostOptions options = options_for(clock);
    options.record_axis_states = true;
    Host host(lcm, program, options);
    ASSERT_EQ(run_loop(host, component, clock), Result::done);
    EXPECT_EQ(host.statistics().axis_states_lost, 1);
    EXPECT_EQ(host.axis_state_gap_text(), "1 axis-state messages lost (first after seq 9)");
    EXPECT_EQ(host.axis_states()[9].seq, 11);
}

}  // namespace
}  // namespace firtp::host::test
