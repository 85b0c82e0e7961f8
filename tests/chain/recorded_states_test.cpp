// FIRTP_AXIS_STATE messages to samples one at a time (AxisStateSamples): where the samples start
// and end, the jerk, and which rests are dropped, against samples written out by hand.
#include <firtp/recorded_states.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace firtp {
namespace {

constexpr double period = 0.001;

firtp_lcm::axis_state_t state(std::int64_t tick, double x, double v, double a, std::int32_t line) {
    firtp_lcm::axis_state_t m{};
    m.seq = tick;
    m.tick = tick;
    m.position[0] = x;
    m.velocity[0] = v;
    m.acceleration[0] = a;
    m.line = line;
    return m;
}

struct Collected {
    std::vector<AxisState> samples;
    AxisStateSamples stream{period, [this](const AxisState& s) { samples.push_back(s); }};
};

std::vector<std::int64_t> ticks(const std::vector<AxisState>& samples, std::int64_t tick0) {
    std::vector<std::int64_t> out;
    for (const AxisState& s : samples) out.push_back(std::llround(s.time / period) + tick0);
    return out;
}

TEST(AxisStateSamples, StartsThePeriodBeforeTheFirstLineAndKeepsOneSampleOfTheFinalRest) {
    Collected c;
    for (std::int64_t t = 10; t < 13; ++t) c.stream.add(state(t, 0, 0, 0, 0));  // waiting
    c.stream.add(state(13, 0.1, 1, 100, 5));
    c.stream.add(state(14, 0.2, 1, 0, 5));
    c.stream.add(state(15, 0.3, 0, -100, 0));  // at rest, idle: the rest's first sample
    EXPECT_EQ(c.samples.size(), 4u);           // each went out as soon as it came
    for (std::int64_t t = 16; t < 20; ++t) c.stream.add(state(t, 0.3, 0, 0, 0));
    EXPECT_EQ(c.samples.size(), 4u);  // held: the rest may be the final one
    c.stream.finish();
    ASSERT_EQ(ticks(c.samples, 12), (std::vector<std::int64_t>{12, 13, 14, 15}));
    EXPECT_EQ(c.samples[0].time, 0.0);
    EXPECT_EQ(c.samples[0].line, 0);
    EXPECT_EQ(c.samples[1].line, 5);
    EXPECT_EQ(c.samples[0].jerk[0], 0.0);
    EXPECT_DOUBLE_EQ(c.samples[1].jerk[0], 100 / period);
    EXPECT_DOUBLE_EQ(c.samples[2].jerk[0], -100 / period);
    EXPECT_EQ(c.stream.count(), 4u);
}

// A stop with no line in the middle of the program is held back (it may be the final rest) and
// given out whole, with its times, once the motion goes on.
TEST(AxisStateSamples, ARestThatEndsInMotionIsKeptWhole) {
    Collected c;
    c.stream.add(state(0, 0, 0, 0, 0));
    c.stream.add(state(1, 0.1, 1, 0, 3));
    c.stream.add(state(2, 0.2, 0, 0, 0));
    for (std::int64_t t = 3; t < 1003; ++t) c.stream.add(state(t, 0.2, 0, 0, 0));
    EXPECT_EQ(c.samples.size(), 3u);  // up to the rest's first sample
    c.stream.add(state(1003, 0.2, 0, 50, 0));  // the same place, accelerating: still held
    EXPECT_EQ(c.samples.size(), 3u);
    c.stream.add(state(1004, 0.25, 1, 50, 4));  // moving again
    c.stream.finish();
    ASSERT_EQ(c.samples.size(), 1005u);
    EXPECT_EQ(ticks(c.samples, 0), [] {
        std::vector<std::int64_t> t;
        for (std::int64_t i = 0; i < 1005; ++i) t.push_back(i);
        return t;
    }());
    for (std::size_t i = 0; i < c.samples.size(); ++i) EXPECT_DOUBLE_EQ(c.samples[i].time, static_cast<double>(i) * period);
    EXPECT_DOUBLE_EQ(c.samples[1003].jerk[0], 50 / period);
    EXPECT_EQ(c.samples[1004].line, 4);
}

TEST(AxisStateSamples, TheBatchFunctionIsTheStream) {
    std::vector<firtp_lcm::axis_state_t> states;
    states.push_back(state(7, 0, 0, 0, 0));
    states.push_back(state(8, 0.1, 1, 10, 2));
    states.push_back(state(9, 0.1, 0, 0, 0));
    states.push_back(state(10, 0.1, 0, 0, 0));
    const std::vector<AxisState> samples = samples_from_axis_states(states, period);
    ASSERT_EQ(samples.size(), 3u);
    EXPECT_EQ(samples.back().time, 2 * period);
}

TEST(AxisStateSamples, NothingMovedIsAnError) {
    Collected c;
    c.stream.add(state(0, 0, 0, 0, 0));
    EXPECT_THROW(c.stream.finish(), std::runtime_error);
    EXPECT_THROW(samples_from_axis_states({}, period), std::runtime_error);
}

}  // namespace
}  // namespace firtp
