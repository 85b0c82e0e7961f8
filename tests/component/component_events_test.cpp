// Program events in the component: in the blocks' sequence, fired when motion reaches them, motion
// waiting at a tool change and a pause, a dwell resting as the plan does.
#include "support/limits.hpp"
#include "support/reference.hpp"
#include "streamed.hpp"

#include <firtp/hal/component_logic.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <deque>
#include <vector>

using namespace firtp;
using firtp::test::xyz;

namespace {

using test::FakeStream;

ComponentSettings paper_settings() {
    ComponentSettings s;
    s.planner.fixed_chain = true;
    s.planner.filters = test::chain_of({0.040, 0.020});
    s.planner.period = 0.001;
    return s;
}

ComponentSettings limit_settings() {
    ComponentSettings s;
    s.planner.limits = test::uniform_limits(200.0, 2000.0, 50000.0);
    s.planner.period = 0.001;
    return s;
}

Block move(double x, double y, Termination termination, std::int64_t line) {
    Block b;
    b.target = xyz(x, y);
    b.feed = 100;
    b.termination = termination;
    b.tolerance = termination == Termination::blend ? 0.05 : 0.0;
    b.line = line;
    return b;
}

using test::streamed;  // through the hal_stream record, as the bridge writes it

struct Program {
    std::deque<stream::BlockRecord> records;
    std::uint64_t seq = 0;
    void block(const Block& b) {
        stream::BlockRecord r;
        r.block = b;
        r.program = 9;
        r.seq = ++seq;
        records.push_back(streamed(r));
    }
    void event(EventKind code, double value, std::int64_t line) {
        stream::BlockRecord r;
        r.is_event = true;
        r.event_code = static_cast<std::int32_t>(code);
        r.event_value = value;
        r.block.line = line;
        r.program = 9;
        r.seq = ++seq;
        records.push_back(streamed(r));
    }
};

struct EventServo {
    explicit EventServo(const ComponentSettings& s) : core(s) {}
    ComponentLogic core;
    FakeStream stream;
    ComponentInputs in;
    ComponentOutputs out;
    std::vector<AxisState> samples;
    std::vector<EventOutputs> events;
    void ticks(int n) {
        for (int k = 0; k < n; ++k) {
            core.update(in, stream.source(), out);
            samples.push_back(out.state);
            events.push_back(out.events);
            in.position_feedback = out.state.position;
            in.velocity_feedback = out.state.velocity;
        }
    }
    bool at(const AxisVector& p) const { return (out.state.position - p).norm() < 1e-12 && out.state.velocity.norm() == 0.0; }
};

// The first move, the dwell, the second move: sample for sample as `firtp plan` (a third block
// follows, so that the look-ahead does not wait for more blocks before the second; compared up to
// the end of the second).
void expect_dwell_as_planned(const ComponentSettings& settings) {
    const Block first = move(20, 0, Termination::exact_stop, 1);
    Block second = move(20, 20, Termination::exact_stop, 3);
    const Block third = move(0, 20, Termination::exact_stop, 4);
    Program program;
    program.block(first);
    program.event(EventKind::dwell, 0.5, 2);
    program.block(second);
    program.block(third);
    EventServo run(settings);
    run.stream.records = program.records;
    run.ticks(2500);
    const Trajectory without = plan_trajectory(settings.planner, AxisVector::Zero(), std::vector<Block>{first, second, third});
    second.dwell = 0.5;
    const Trajectory plan = plan_trajectory(settings.planner, AxisVector::Zero(), std::vector<Block>{first, second, third});
    std::size_t second_done = 0;
    while (second_done < plan.samples.size() && plan.samples[second_done].position != second.target) ++second_done;
    ASSERT_LT(second_done, plan.samples.size());
    ASSERT_GE(run.samples.size(), second_done);
    for (std::size_t k = 0; k <= second_done; ++k)
        ASSERT_EQ(run.samples[k].position, plan.samples[k].position) << "tick " << k;
    EXPECT_NEAR(plan.cycle_time, without.cycle_time + 0.5, 1.01 * settings.planner.period);
    EXPECT_EQ(run.out.events.events, 1u);
    EXPECT_EQ(run.out.next_seq, 5u);
    EXPECT_EQ(run.out.rejected, 0u);
}

}  // namespace

TEST(ComponentEvents, ADwellRestsAsThePlanWithThePapersChain) { expect_dwell_as_planned(paper_settings()); }

TEST(ComponentEvents, ADwellRestsAsThePlanAtTheLimits) { expect_dwell_as_planned(limit_settings()); }

TEST(ComponentEvents, EventsFireWhenMotionReachesThemInOrder) {
    const Block first = move(10, 0, Termination::exact_stop, 1);
    Program program;
    program.event(EventKind::spindle_speed, 8000, 1);
    program.event(EventKind::spindle_clockwise, 8000, 1);
    program.block(first);
    program.event(EventKind::flood_on, 0, 2);
    program.block(move(10, 10, Termination::blend, 3));
    program.event(EventKind::program_end, 0, 4);
    EventServo run(paper_settings());
    run.stream.records = program.records;
    run.ticks(1);
    EXPECT_TRUE(run.out.events.spindle_on);  // before the first block: at once
    EXPECT_TRUE(run.out.events.spindle_forward);
    EXPECT_EQ(run.out.events.spindle_speed, 8000.0);
    EXPECT_FALSE(run.out.events.coolant_flood);
    // Flood comes on at the first sample at which the tool rests at the end of the first block.
    int flood_at = -1, end_at = -1;
    for (int k = 1; k < 2000 && end_at < 0; ++k) {
        run.ticks(1);
        if (flood_at < 0 && run.out.events.coolant_flood) flood_at = k;
        if (run.out.events.program_end) end_at = k;
    }
    ASSERT_GT(flood_at, 0);
    EXPECT_EQ(run.samples[static_cast<std::size_t>(flood_at)].position, first.target);
    EXPECT_NE(run.samples[static_cast<std::size_t>(flood_at) - 1].position, first.target);
    ASSERT_GT(end_at, flood_at);
    EXPECT_TRUE(run.at(xyz(10, 10)));  // the end fires with the last block done
    EXPECT_FALSE(run.out.events.spindle_on);  // M2 stops the spindle and the coolant, as LinuxCNC
    EXPECT_FALSE(run.out.events.coolant_flood);
    EXPECT_EQ(run.out.events.events, 4u);
}

TEST(ComponentEvents, AToolChangeWaitsAtRestForToolChanged) {
    const Block first = move(10, 0, Termination::exact_stop, 1);
    Program program;
    program.block(first);
    program.event(EventKind::tool_select, 3, 2);
    program.event(EventKind::tool_change, 3, 2);
    program.block(move(10, 10, Termination::exact_stop, 3));
    EventServo run(limit_settings());
    run.stream.records = program.records;
    int change_at = -1;
    for (int k = 0; k < 3000 && change_at < 0; ++k) {
        run.ticks(1);
        if (run.out.events.tool_change) change_at = k;
    }
    ASSERT_GE(change_at, 0);
    EXPECT_TRUE(run.at(first.target));
    EXPECT_EQ(run.out.events.tool_prep_number, 3);
    EXPECT_EQ(run.out.events.tool_number, 0);
    run.ticks(1000);  // nobody changes the tool: motion waits
    EXPECT_TRUE(run.at(first.target));
    EXPECT_TRUE(run.out.events.tool_change);
    EXPECT_EQ(run.out.next_seq, 4u);  // the block after the change is not taken yet
    run.in.events.tool_changed = true;
    run.ticks(3000);
    EXPECT_FALSE(run.out.events.tool_change);
    EXPECT_EQ(run.out.events.tool_number, 3);
    EXPECT_TRUE(run.at(xyz(10, 10)));
    EXPECT_EQ(run.out.next_seq, 5u);
}

// A tool change between exact stops, tool-changed looped back as `firtp run` nets it: the block
// after the change is the last one the component has (the next change gates the stream), but its
// exact stop is its own, so it starts at once instead of waiting start_wait for more blocks. Each
// block starts at most two periods after it does in `firtp plan` (the handshake).
TEST(ComponentEvents, ABlockBeforeAToolChangeStartsAtOnce) {
    const std::vector<Block> blocks{move(10, 0, Termination::exact_stop, 1), move(10, 10, Termination::exact_stop, 3),
                                    move(0, 10, Termination::exact_stop, 5)};
    Program program;
    program.block(blocks[0]);
    program.event(EventKind::tool_change, 2, 2);
    program.block(blocks[1]);
    program.event(EventKind::tool_change, 3, 4);
    program.block(blocks[2]);
    program.event(EventKind::program_end, 0, 6);
    const ComponentSettings settings = limit_settings();
    EventServo run(settings);
    run.stream.records = program.records;
    for (int k = 0; k < 5000; ++k) {
        run.in.events.tool_changed = run.out.events.tool_change;  // net tool-change tool-changed
        run.ticks(1);
    }
    ASSERT_TRUE(run.at(blocks[2].target));
    const Trajectory plan = plan_trajectory(settings.planner, AxisVector::Zero(), blocks);
    // When each block's motion starts (the first sample that leaves its start point), in ticks.
    auto starts = [&](const std::vector<AxisState>& samples) {
        std::vector<std::size_t> out;
        AxisVector from = AxisVector::Zero();
        std::size_t b = 0;
        for (std::size_t k = 0; k < samples.size() && b < blocks.size(); ++k) {
            if (samples[k].position != from && (out.size() == b)) out.push_back(k);
            if (samples[k].position == blocks[b].target && samples[k].velocity.norm() == 0.0) from = blocks[b++].target;
        }
        return out;
    };
    const std::vector<std::size_t> planned = starts(plan.samples), ran = starts(run.samples);
    ASSERT_EQ(planned.size(), 3u);
    ASSERT_EQ(ran.size(), 3u);
    EXPECT_EQ(ran[0], planned[0]);
    for (std::size_t b = 1; b < 3; ++b) {
        EXPECT_GE(ran[b], planned[b] + (ran[b - 1] - planned[b - 1])) << "block " << b;
        EXPECT_LE(ran[b], planned[b] + (ran[b - 1] - planned[b - 1]) + 2) << "block " << b << ": waited for more blocks";
    }
}

TEST(ComponentEvents, APauseWaitsForResumeAndM1OnlyWithOptionalStop) {
    Program program;
    program.block(move(10, 0, Termination::exact_stop, 1));
    program.event(EventKind::optional_pause, 0, 2);  // optional-stop off: goes on
    program.block(move(10, 10, Termination::exact_stop, 3));
    program.event(EventKind::pause, 0, 4);
    program.block(move(0, 10, Termination::exact_stop, 5));
    EventServo run(paper_settings());
    run.stream.records = program.records;
    run.ticks(3000);
    EXPECT_TRUE(run.at(xyz(10, 10)));
    EXPECT_TRUE(run.out.events.paused);
    EXPECT_EQ(run.out.events.line, 4);
    run.in.events.resume = true;
    run.ticks(3000);
    EXPECT_FALSE(run.out.events.paused);
    EXPECT_TRUE(run.at(xyz(0, 10)));
}

TEST(ComponentEvents, AGapOrARepeatAmongEventsIsCaught) {
    Program program;
    program.block(move(10, 0, Termination::exact_stop, 1));
    program.event(EventKind::flood_on, 0, 2);
    stream::BlockRecord repeat = program.records.back();
    program.records.push_back(repeat);  // the same event again: never twice
    EventServo run(paper_settings());
    run.stream.records = program.records;
    run.ticks(2000);
    EXPECT_EQ(run.out.error, ComponentError::repeated);
    EXPECT_EQ(run.out.events.events, 1u);

    Program gap;
    gap.block(move(10, 0, Termination::exact_stop, 1));
    ++gap.seq;  // seq 2 lost
    gap.event(EventKind::flood_on, 0, 2);
    EventServo lost(paper_settings());
    lost.stream.records = gap.records;
    lost.ticks(2000);
    EXPECT_EQ(lost.out.error, ComponentError::sequence_gap);
    EXPECT_EQ(lost.out.events.events, 0u);
    EXPECT_FALSE(lost.out.events.coolant_flood);
}

TEST(ComponentEvents, AnUnknownEventCodeStopsTheProgram) {
    Program program;
    program.block(move(10, 0, Termination::exact_stop, 1));
    program.event(static_cast<EventKind>(event_kinds), 0, 2);
    EventServo run(paper_settings());
    run.stream.records = program.records;
    run.ticks(2000);
    EXPECT_EQ(run.out.error, ComponentError::bad_type);
}
