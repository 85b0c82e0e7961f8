// Operator controls reach the component as levels with a rising seq, republished periodically.
#include "test_support.hpp"

#include <gtest/gtest.h>

namespace firtp::host::test {
namespace {

struct ControlTest : ::testing::Test {
    lcm::LCM lcm{"memq://"};
    FakeClock clock;
    FakeComponent component{lcm, 8};
    Program program = line_program(200);

    void SetUp() override { component.ticks_per_block = 20; }
    void run_for(Host& host, int ticks) {
        for (int t = 0; t < ticks; ++t) {
            host.step();
            component.tick();
            clock.advance(1ms);
        }
    }
    void expect_rising_seq() const {
        for (std::size_t i = 1; i < component.controls.size(); ++i)
            EXPECT_EQ(component.controls[i].seq, component.controls[i - 1].seq + 1);
    }
};

TEST_F(ControlTest, LevelsArePublishedAtStartAndRepublished) {
    Host host(lcm, program, options_for(clock));
    run_for(host, 1000);
    ASSERT_GE(component.controls.size(), 10u);
    EXPECT_LE(component.controls.size(), 12u);
    EXPECT_EQ(component.controls.front().seq, 1);
    EXPECT_EQ(component.controls.front().feed_scale, 1.0);
    EXPECT_FALSE(component.controls.front().hold);
    EXPECT_FALSE(component.controls.front().abort);
    expect_rising_seq();
}

TEST_F(ControlTest, FeedHoldAbortReachTheComponent) {
    Host host(lcm, program, options_for(clock));
    run_for(host, 10);
    host.set_feed_scale(0.8);
    run_for(host, 10);
    EXPECT_EQ(component.feed_scale(), 0.8);
    EXPECT_EQ(host.progress().feed_in_effect, 0.8);
    host.hold(true);
    run_for(host, 10);
    EXPECT_TRUE(component.hold());
    EXPECT_TRUE(host.progress().hold);
    host.hold(false);
    run_for(host, 10);
    EXPECT_FALSE(component.hold());
    host.abort();
    run_for(host, 1);
    EXPECT_TRUE(component.abort());
    EXPECT_EQ(component.controls.back().feed_scale, 0.8);
    expect_rising_seq();
}

TEST_F(ControlTest, ChangesGoOutAtOnce) {
    Host host(lcm, program, options_for(clock));
    run_for(host, 1);
    while (lcm.handleTimeout(0) > 0) {}
    const std::size_t before = component.controls.size();
    host.set_feed_scale(0.5);
    host.hold(true);
    while (lcm.handleTimeout(0) > 0) {}
    EXPECT_EQ(component.controls.size(), before + 2);
    EXPECT_EQ(component.controls.back().feed_scale, 0.5);
    EXPECT_TRUE(component.controls.back().hold);
}

TEST_F(ControlTest, FeedScaleIsClampedToTheMaximum) {
    HostOptions options = options_for(clock);
    options.max_feed_scale = 1.2;
    Host host(lcm, program, options);
    host.set_feed_scale(3.0);
    run_for(host, 2);
    EXPECT_EQ(component.feed_scale(), 1.2);
    host.set_feed_scale(-1.0);
    run_for(host, 2);
    EXPECT_EQ(component.feed_scale(), 0.0);
    host.set_feed_scale(std::nan(""));
    run_for(host, 2);
    EXPECT_EQ(component.feed_scale(), 0.0);
    EXPECT_EQ(host.max_feed_scale(), 1.2);
}

TEST_F(ControlTest, LostControlIsRepairedByTheRepublish) {
    Host host(lcm, program, options_for(clock));
    run_for(host, 5);
    component.drop_controls = 1;
    host.hold(true);  // this message is lost
    run_for(host, 50);
    EXPECT_FALSE(component.hold());
    run_for(host, 100);
    EXPECT_TRUE(component.hold());
}

}  // namespace
}  // namespace firtp::host::test
