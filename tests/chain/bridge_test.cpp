// LCM messages into the real component through firtp-bridge: bad values, gaps, repeats and
// reordering are reported in FIRTP_STATUS, and no block runs twice or is dropped silently.
#include "chain_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace firtp;
using test::block_message;

namespace {

// Short filters and no axis limits: these tests are about messages, not motion.
MachineConfig machine() {
    MachineConfig m = default_machine();
    m.given_times = {0.02, 0.01};
    m.limits = MachineLimits{};
    return m;
}

}  // namespace

TEST(Bridge, RunsAProgramAndReportsProgress) {
    test::Chain chain(machine());
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

TEST(Bridge, NanBlockIsRefusedNamingSeqAndLineAndStopsTheProgram) {
    test::Chain chain(machine());
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
    test::Chain chain(machine());
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
    test::Chain chain(machine());
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
    test::Chain chain(machine());
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
    chain.lcm->publish(messages::control_channel, &stale);
    chain.run(2);
    EXPECT_EQ(chain.status().feed_scale, 1.0);
}

TEST(Bridge, HoldStopsOnThePathAndResumes) {
    test::Chain chain(machine());
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
    test::Chain chain(machine());
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
