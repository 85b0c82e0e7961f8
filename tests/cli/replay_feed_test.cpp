// firtp replay's schedule (replay_feed.hpp) and its one-to-one comparison (replay_compare.hpp), on
// made-up logs: each taken block and each applied control once, in the period its axis state
// names; resent and repeated copies left out; blocks never taken and controls never applied where
// they were logged. And the log reader (replay_log.hpp) on a log written with lcm::LogFile: axis
// states from before control_session and control_seq are refused by name.
#include "replay_compare.hpp"
#include "replay_feed.hpp"
#include "replay_log.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

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
    void control(std::int64_t session = 0, std::int64_t seq = 0) {
        LoggedEvent e;
        e.eventnum = static_cast<std::int64_t>(run.events.size());
        e.channel = messages::control_channel;
        e.program = session;
        e.seq = seq;
        run.events.push_back(e);
    }
    // control_session, control_seq: the control applied in the state's period (0, 0: none).
    void state(std::int64_t program, std::int64_t next_seq, std::int64_t control_session = 0,
               std::int64_t control_seq = 0) {
        firtp_lcm::axis_state_t s{};
        s.seq = static_cast<std::int64_t>(run.states.size()) + 1;
        s.tick = s.seq - 1;
        s.program = program;
        s.next_seq = next_seq;
        s.control_session = control_session;
        s.control_seq = control_seq;
        LoggedEvent e;
        e.kind = LoggedEvent::Kind::state;
        e.eventnum = static_cast<std::int64_t>(run.events.size());
        e.state = run.states.size();
        run.states.push_back(s);
        run.events.push_back(e);
    }
    LoggedRun run;
};

// "b<program>.<seq>" for blocks, "e<program>.<seq>" for program events, "c<session>.<seq>" for
// controls ("c" for those of session 0, seq 0), per period.
std::vector<std::string> names(const std::vector<const LoggedEvent*>& inputs) {
    std::vector<std::string> out;
    for (const LoggedEvent* e : inputs) {
        const std::string channel = e->channel;
        std::string name = channel == messages::block_channel ? "b" : channel == messages::event_channel ? "e" : "c";
        if (name != "c" || e->seq != 0) name.append(std::to_string(e->program)).append(".").append(std::to_string(e->seq));
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

// Controls reach the bridge at any time; the component applies them at its next period, and every
// axis state names the control applied (control_session, control_seq). Logged before a state is
// not applied in that state's period: the replay feeds each where its state names it.
TEST(ReplayFeed, EachAppliedControlOnceInThePeriodThatAppliedIt) {
    Log log;
    log.block(7, 1);
    log.control(5, 1);
    log.state(0, 1);        // logged after control 5.1, but its period ran before the bridge took it
    log.state(7, 2, 5, 1);  // 5.1 applied here (and block 7.1 taken)
    log.control(5, 2), log.control(5, 3);  // both taken by the bridge before one period: 5.2 superseded
    log.control(5, 2);                      // a repeated copy of a taken control: left out
    log.state(7, 2, 5, 1);  // the period ran before the bridge took them
    log.state(7, 2, 5, 3);
    log.control(5, 1);  // a late copy of an applied control: left out (the bridge ignores it as older)
    log.control(5, 4);  // taken after the last period: never applied, where it was logged
    const FeedSchedule s = feed_schedule(log.run);
    ASSERT_EQ(s.before.size(), 5u);
    EXPECT_EQ(names(s.before[0]), Names{});
    EXPECT_EQ(names(s.before[1]), (Names{"b7.1", "c5.1"}));
    EXPECT_EQ(names(s.before[2]), Names{});
    EXPECT_EQ(names(s.before[3]), (Names{"c5.2", "c5.3"}));
    EXPECT_EQ(names(s.before[4]), Names{"c5.4"});
    EXPECT_EQ(s.controls_placed_by_state, 3u);
    EXPECT_EQ(s.placed_by_state, 1u);
}

// Taken in one period, blocks and controls keep the order they were logged in (an abort taken
// before a block would have refused it), each in its own sequence.
TEST(ReplayFeed, ControlsAndBlocksOfOnePeriodInterleaveAsLogged) {
    Log log;
    log.control(2, 1), log.block(3, 1), log.control(2, 2), log.block(3, 2);
    log.state(3, 3, 2, 2);
    log.block(3, 4), log.block(3, 3), log.control(2, 3);  // block 4's first copy before 3's (refused, resent)
    log.state(3, 5, 2, 3);
    const FeedSchedule s = feed_schedule(log.run);
    EXPECT_EQ(names(s.before[0]), (Names{"c2.1", "b3.1", "c2.2", "b3.2"}));
    EXPECT_EQ(names(s.before[1]), (Names{"b3.3", "b3.4", "c2.3"}));  // each sequence in its order
}

// A new host (session) counts from 1; a late message of the old session that no state names stays
// where it was logged.
TEST(ReplayFeed, ANewControlSessionStartsItsOwnCount) {
    Log log;
    log.control(5, 1), log.control(5, 2);
    log.state(0, 1, 5, 2);
    log.control(9, 1);
    log.state(0, 1, 9, 1);
    log.control(5, 3);
    log.state(0, 1, 9, 1);
    const FeedSchedule s = feed_schedule(log.run);
    EXPECT_EQ(names(s.before[0]), (Names{"c5.1", "c5.2"}));
    EXPECT_EQ(names(s.before[1]), Names{"c9.1"});
    EXPECT_EQ(names(s.before[2]), Names{"c5.3"});
    EXPECT_EQ(s.controls_placed_by_state, 3u);
}

TEST(ReplayFeed, AnAppliedControlTheLogDoesNotHoldIsNamed) {
    Log log;
    log.control(4, 2);
    log.state(0, 1, 4, 2);
    log.state(0, 1, 4, 3);  // the recorder missed control 4.3
    try {
        feed_schedule(log.run);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("FIRTP_AXIS_STATE seq 2 (log event 2) says control session 4 seq 3 was "
                                             "taken, but the log does not hold it"),
                  std::string::npos) << e.what();
    }
}

// Written with lcm::LogFile: a block, then an axis state of the type before control_session and
// control_seq (its fingerprint, without those 16 bytes, sealed): refused naming the two fields.
TEST(ReplayLog, AxisStatesFromBeforeTheControlFieldsAreRefusedByName) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("firtp_old_states_" + std::to_string(getpid()) + ".lcmlog");
    {
        lcm::LogFile file(path.string(), "w");
        ASSERT_TRUE(file.good());
        firtp_lcm::block_t block = messages::to_message(Block{}, 1, 1, 0);
        block.feed = 10.0;
        block.tolerance = 0.1;
        std::vector<std::uint8_t> bytes = messages::seal_encoded(block);
        lcm::LogEvent event{0, 0, messages::block_channel, static_cast<std::int32_t>(bytes.size()), bytes.data()};
        file.writeEvent(&event);
        firtp_lcm::axis_state_t state{};
        state.seq = 1;
        bytes = messages::seal_encoded(state);
        bytes.erase(bytes.end() - 4 - 16, bytes.end() - 4);  // control_session, control_seq
        const std::uint64_t old_fingerprint = 0xc4dee41eef8eeb16;
        for (int i = 0; i < 8; ++i) bytes[i] = static_cast<std::uint8_t>(old_fingerprint >> (56 - 8 * i));
        const std::uint32_t crc = messages::crc32(bytes.data(), bytes.size() - 4);
        for (int i = 0; i < 4; ++i) bytes[bytes.size() - 4 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
        event = lcm::LogEvent{1, 1000, messages::axis_state_channel, static_cast<std::int32_t>(bytes.size()), bytes.data()};
        file.writeEvent(&event);
    }
    try {
        read_logged_run(path);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("event 1 on FIRTP_AXIS_STATE: an axis_state_t without control_session and "
                                             "control_seq"),
                  std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
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
    replayed[1].control_seq = 4;  // the replay applied a control in another period
    ASSERT_TRUE(compare_states(recorded, replayed, 3, 0.0).first);
    EXPECT_EQ(compare_states(recorded, replayed, 3, 0.0).first->what, "control_seq");
    replayed[1] = recorded[1];
    replayed.pop_back();
    ASSERT_TRUE(compare_states(recorded, replayed, 3, 0.0).first);
    EXPECT_EQ(compare_states(recorded, replayed, 3, 0.0).first->what, "missing");
}

}  // namespace
}  // namespace firtp::cli
