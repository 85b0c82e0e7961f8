// firtp replay's schedule (replay_feed.hpp) and its one-to-one comparison (replay_compare.hpp), on
// made-up logs: each taken block once, in the period its axis state names; resent copies left out;
// blocks never taken and controls where they were logged.
#include "replay_compare.hpp"
#include "replay_feed.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace firtp::cli {
namespace {

class Log {
public:
    void block(std::int64_t program, std::int64_t seq) {
        LoggedEvent e;
        e.eventnum = static_cast<std::int64_t>(run.events.size());
        e.channel = messages::block_channel;
        e.program = program;
        e.seq = seq;
        run.events.push_back(e);
    }
    void program_event(std::int64_t program, std::int64_t seq) {
        LoggedEvent e;
        e.eventnum = static_cast<std::int64_t>(run.events.size());
        e.channel = messages::event_channel;
        e.program = program;
        e.seq = seq;
        run.events.push_back(e);
    }
    void control() {
        LoggedEvent e;
        e.eventnum = static_cast<std::int64_t>(run.events.size());
        e.channel = messages::control_channel;
        run.events.push_back(e);
    }
    void state(std::int64_t program, std::int64_t next_seq) {
        firtp_lcm::axis_state_t s{};
        s.seq = static_cast<std::int64_t>(run.states.size()) + 1;
        s.tick = s.seq - 1;
        s.program = program;
        s.next_seq = next_seq;
        LoggedEvent e;
        e.kind = LoggedEvent::Kind::state;
        e.eventnum = static_cast<std::int64_t>(run.events.size());
        e.state = run.states.size();
        run.states.push_back(s);
        run.events.push_back(e);
    }
    LoggedRun run;
};

// "b<program>.<seq>" for blocks, "e<program>.<seq>" for program events, "c" for controls, per period.
std::vector<std::string> names(const std::vector<const LoggedEvent*>& inputs) {
    std::vector<std::string> out;
    for (const LoggedEvent* e : inputs) {
        const std::string channel = e->channel;
        std::string name = channel == messages::block_channel ? "b" : channel == messages::event_channel ? "e" : "c";
        if (name != "c") name.append(std::to_string(e->program)).append(".").append(std::to_string(e->seq));
        out.push_back(name);
    }
    return out;
}

using Names = std::vector<std::string>;

TEST(ReplayFeed, EachTakenBlockOnceInThePeriodThatTookIt) {
    Log log;
    log.control();
    log.block(7, 1), log.block(7, 2), log.block(7, 3), log.block(7, 4);  // a burst, taken over three periods
    log.state(0, 1);
    log.state(7, 2);
    log.block(7, 3);  // a resend of a taken block: left out
    log.control();
    log.state(7, 2);
    log.state(7, 5);
    log.block(7, 5);  // never taken (the program was stopped): where it was logged
    const FeedSchedule s = feed_schedule(log.run);
    ASSERT_EQ(s.before.size(), 5u);
    EXPECT_EQ(names(s.before[0]), Names{"c"});
    EXPECT_EQ(names(s.before[1]), Names{"b7.1"});
    EXPECT_EQ(names(s.before[2]), Names{"c"});
    EXPECT_EQ(names(s.before[3]), (Names{"b7.2", "b7.3", "b7.4"}));
    EXPECT_EQ(names(s.before[4]), Names{"b7.5"});
    EXPECT_EQ(s.placed_by_state, 4u);
}

TEST(ReplayFeed, ANewProgramStartsFromItsFirstBlock) {
    Log log;
    log.block(1, 1), log.block(2, 1), log.block(2, 2);
    log.state(1, 2);
    log.state(2, 3);
    const FeedSchedule s = feed_schedule(log.run);
    EXPECT_EQ(names(s.before[0]), Names{"b1.1"});
    EXPECT_EQ(names(s.before[1]), (Names{"b2.1", "b2.2"}));
}

// Program events (spindle, tool, dwell, end) share the blocks' sequence: taken in the same periods.
TEST(ReplayFeed, ProgramEventsGoInWithTheBlocksAroundThem) {
    Log log;
    log.block(3, 1), log.program_event(3, 2), log.block(3, 3), log.program_event(3, 4);
    log.state(3, 3);
    log.state(3, 5);
    const FeedSchedule s = feed_schedule(log.run);
    EXPECT_EQ(names(s.before[0]), (Names{"b3.1", "e3.2"}));
    EXPECT_EQ(names(s.before[1]), (Names{"b3.3", "e3.4"}));
    EXPECT_EQ(s.placed_by_state, 4u);
}

TEST(ReplayFeed, ATakenBlockTheLogDoesNotHoldIsNamed) {
    Log log;
    log.block(7, 2);
    log.state(7, 3);  // block 1 was taken before the recorder started
    try {
        feed_schedule(log.run);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("FIRTP_AXIS_STATE seq 1 (log event 1) says program 7 block seq 1 was taken"),
                  std::string::npos) << e.what();
    }
}

TEST(ReplayCompare, OneToOneBitForBitAndNamesTheFirstDifference) {
    std::vector<firtp_lcm::axis_state_t> recorded(4), replayed(4);
    for (int i = 0; i < 4; ++i) recorded[i].position[1] = replayed[i].position[1] = 0.1 * i;
    EXPECT_FALSE(compare_states(recorded, replayed, 3, 0.0).first);
    replayed[2].position[1] = std::nextafter(replayed[2].position[1], 1.0);
    const Comparison c = compare_states(recorded, replayed, 3, 0.0);
    ASSERT_TRUE(c.first);
    EXPECT_EQ(c.first->recorded, 2u);
    EXPECT_EQ(c.first->what, "position");
    EXPECT_EQ(c.first->axis, 1);
    EXPECT_FALSE(compare_states(recorded, replayed, 3, 1e-12).first);  // within a relative tolerance
    replayed[2] = recorded[2];
    replayed[3].next_seq = 9;  // the replay took a block in another period
    ASSERT_TRUE(compare_states(recorded, replayed, 3, 0.0).first);
    EXPECT_EQ(compare_states(recorded, replayed, 3, 0.0).first->what, "next_seq");
    replayed[3] = recorded[3];
    replayed.pop_back();
    ASSERT_TRUE(compare_states(recorded, replayed, 3, 0.0).first);
    EXPECT_EQ(compare_states(recorded, replayed, 3, 0.0).first->what, "missing");
}

}  // namespace
}  // namespace firtp::cli
