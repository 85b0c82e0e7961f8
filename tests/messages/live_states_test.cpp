// publish_live(): the one decimation rule of FIRTP_AXIS_STATE_LIVE (the bridge's and the LinuxCNC
// bridge's), on memq://.
#include "sample.hpp"

#include <vector>

namespace firtp::messages {
namespace {

struct Live {
    std::vector<firtp_lcm::axis_state_t> states;
    void on(const lcm::ReceiveBuffer* b, const std::string&) {
        const auto r = receive<firtp_lcm::axis_state_t>(b->data, b->data_size);
        ASSERT_FALSE(r.problem) << *r.problem;
        states.push_back(r.message);
    }
};

std::vector<firtp_lcm::axis_state_t> live_states(int decimation, std::int64_t ticks) {
    const auto lcm = open("memq://");
    Live live;
    lcm->subscribe(axis_state_live_channel, &Live::on, &live);
    firtp_lcm::axis_state_t state = test::sample_axis_state();
    for (std::int64_t tick = 0; tick < ticks; ++tick) {
        state.tick = tick;
        state.seq = 1000 + tick;  // the every-period seq: not the live one
        EXPECT_EQ(publish_live(*lcm, state, decimation), tick % (decimation > 0 ? decimation : 1) == 0 && decimation > 0);
    }
    while (lcm->handleTimeout(0) > 0) {
    }
    return live.states;
}

TEST(LiveStates, EveryNthTickWithSeqTickOverN) {
    const auto states = live_states(20, 45);
    ASSERT_EQ(states.size(), 3u);
    for (std::size_t i = 0; i < states.size(); ++i) {
        EXPECT_EQ(states[i].tick, std::int64_t(20 * i));
        EXPECT_EQ(states[i].seq, std::int64_t(i));
        EXPECT_EQ(states[i].position[0], test::sample_axis_state().position[0]);
    }
}

TEST(LiveStates, DecimationZeroPublishesNothing) { EXPECT_TRUE(live_states(0, 45).empty()); }

TEST(LiveStates, DecimationOneIsEveryTick) {
    const auto states = live_states(1, 5);
    ASSERT_EQ(states.size(), 5u);
    EXPECT_EQ(states.back().seq, 4);
}

}  // namespace
}  // namespace firtp::messages
