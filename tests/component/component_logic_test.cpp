// The component's real-time logic: blocks through the stream or the pins, sequence numbers,
// errors that stop the program on the path, abort, disable.
#include "support/limits.hpp"
#include "support/reference.hpp"
#include "streamed.hpp"

#include <firtp/hal/component_logic.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <deque>

using namespace firtp;
using firtp::test::xyz;

namespace {

using test::FakeStream;

ComponentSettings settings() {
    ComponentSettings s;
    s.planner.fixed_chain = true;
    s.planner.filters = test::chain_of({0.148, 0.089});
    s.planner.period = 0.001;
    return s;
}

std::vector<Block> diamond() {
    std::vector<Block> blocks;
    for (const AxisVector& p : {xyz(25, 25), xyz(50, 0), xyz(25, -25), xyz(0, 0)}) {
        Block b;
        b.target = p;
        b.feed = 250;
        b.tolerance = 0.5;
        b.line = static_cast<std::int64_t>(blocks.size() + 5);
        blocks.push_back(b);
    }
    return blocks;
}

stream::BlockRecord record(const Block& b, std::uint64_t program, std::uint64_t seq) {
    stream::BlockRecord r;
    r.block = b;
    r.program = program;
    r.seq = seq;
    return r;
}

using test::streamed;  // through the hal_stream record, as the bridge writes it

struct Servo {
    explicit Servo(const ComponentSettings& s = settings()) : core(s) {}
    ComponentLogic core;
    FakeStream stream;
    ComponentInputs in;
    ComponentOutputs out;
    std::vector<AxisState> samples;
    bool ideal_drive = true;  // the feedback is the last command
    void ticks(int n) {
        for (int k = 0; k < n; ++k) {
            core.update(in, stream.source(), out);
            samples.push_back(out.state);
            if (ideal_drive) {
                in.position_feedback = out.state.position;
                in.velocity_feedback = out.state.velocity;
            }
        }
    }
};

}  // namespace

TEST(ComponentLogic, StreamedBlocksGiveThePlannedTrajectory) {
    Servo run;
    const std::vector<Block> blocks = diamond();
    for (std::uint32_t i = 0; i < blocks.size(); ++i) run.stream.records.push_back(record(blocks[i], 7, i + 1));
    run.ticks(1300);
    const Trajectory plan = plan_trajectory(settings().planner, AxisVector::Zero(), blocks);
    ASSERT_GE(run.samples.size(), plan.samples.size());
    for (std::size_t k = 0; k < plan.samples.size(); ++k) {
        ASSERT_EQ(run.samples[k].position, plan.samples[k].position) << "tick " << k;
        ASSERT_EQ(run.samples[k].velocity, plan.samples[k].velocity) << "tick " << k;
    }
    EXPECT_EQ(run.out.mode, ComponentState::idle);
    EXPECT_TRUE(run.out.done);
    EXPECT_EQ(run.out.next_seq, 5u);
    EXPECT_EQ(run.out.rejected, 0u);
}

TEST(ComponentLogic, PlansAtMostTheConfiguredBlocksPerPeriod) {
    ComponentSettings s = settings();
    s.max_blocks_per_period = 3;
    ComponentLogic core(s);
    FakeStream stream;
    for (std::uint32_t i = 0; i < 10; ++i) {
        Block b = diamond()[i % 4];
        b.target = xyz(i + 1.0, 0);
        stream.records.push_back(record(b, 1, i + 1));
    }
    ComponentOutputs out;
    core.update({}, stream.source(), out);
    EXPECT_EQ(stream.reads, 3);
    EXPECT_EQ(out.next_seq, 4u);
}

TEST(ComponentLogic, GapStopsOnThePathAndRefusesTheRestUntilANewProgram) {
    Servo run;
    const std::vector<Block> blocks = diamond();
    run.stream.records.push_back(record(blocks[0], 1, 1));
    run.ticks(50);
    run.stream.records.push_back(record(blocks[2], 1, 3));  // seq 2 lost
    run.stream.records.push_back(record(blocks[3], 1, 4));
    run.ticks(1000);
    EXPECT_EQ(run.out.error, ComponentError::sequence_gap);
    EXPECT_EQ(run.out.mode, ComponentState::error);
    EXPECT_EQ(run.out.rejected, 2u);
    // Stopped on the first block's line, short of its end: nothing of seq 3 or 4 ran.
    const AxisVector at = run.samples.back().position;
    EXPECT_NEAR(at[0], at[1], 1e-9);
    EXPECT_LT(at[0], 25.0);
    EXPECT_EQ(run.samples.back().velocity, AxisVector::Zero());
    // A new program starts from where the tool stopped.
    Block home = blocks[3];
    run.stream.records.push_back(record(home, 2, 1));
    run.ticks(1000);
    EXPECT_EQ(run.out.error, ComponentError::none);
    EXPECT_EQ(run.samples.back().position, xyz(0, 0));
}

TEST(ComponentLogic, RepeatedBlockIsNotRunTwice) {
    Servo run;
    const std::vector<Block> blocks = diamond();
    run.stream.records.push_back(record(blocks[0], 1, 1));
    run.stream.records.push_back(record(blocks[0], 1, 1));
    run.stream.records.push_back(record(blocks[1], 1, 2));
    run.ticks(1000);
    EXPECT_EQ(run.out.error, ComponentError::repeated);
    EXPECT_EQ(run.out.rejected, 1u);
    EXPECT_EQ(run.out.mode, ComponentState::idle);  // harmless: the program went on
    EXPECT_EQ(run.samples.back().position, xyz(50, 0));
}

TEST(ComponentLogic, BadValueOrTypeStopsTheProgram) {
    for (int kind = 0; kind < 2; ++kind) {
        Servo run;
        const std::vector<Block> blocks = diamond();
        run.stream.records.push_back(record(blocks[0], 1, 1));
        stream::BlockRecord bad = record(blocks[1], 1, 2);
        if (kind == 0) bad.block.feed = std::numeric_limits<double>::quiet_NaN();
        else bad.type_known = false;
        run.stream.records.push_back(bad);
        run.stream.records.push_back(record(blocks[2], 1, 3));
        run.ticks(1200);
        EXPECT_EQ(run.out.error, kind == 0 ? ComponentError::bad_value : ComponentError::bad_type);
        EXPECT_EQ(run.out.mode, ComponentState::error);
        EXPECT_LT(run.samples.back().position[0], 25.0 + 1e-9);  // never turned towards X50
        EXPECT_TRUE(run.samples.back().position.allFinite());
    }
}

TEST(ComponentLogic, PinHandshakeTakesOneBlockPerStrobe) {
    Servo run;
    run.in.strobe = true;
    run.in.pin_block.block = diamond()[0];
    run.in.pin_block.block.tolerance = 0.0;  // -> the default tolerance
    run.ticks(5);
    EXPECT_TRUE(run.out.ack);
    EXPECT_EQ(run.out.queue_depth, 1);
    run.in.strobe = false;
    run.ticks(1);
    EXPECT_FALSE(run.out.ack);
    run.in.pin_block.block = diamond()[1];
    run.in.strobe = true;
    run.ticks(1000);
    EXPECT_EQ(run.samples.back().position, xyz(50, 0));
}

TEST(ComponentLogic, AbortStopsOnThePathAndDropsTheQueue) {
    Servo run;
    const std::vector<Block> blocks = diamond();
    for (std::uint32_t i = 0; i < blocks.size(); ++i) run.stream.records.push_back(record(blocks[i], 1, i + 1));
    run.ticks(100);
    run.in.abort = true;
    run.ticks(400);
    EXPECT_TRUE(run.out.done);
    EXPECT_EQ(run.samples.back().velocity, AxisVector::Zero());
    const AxisVector at = run.samples.back().position;
    EXPECT_NEAR(at[0], at[1], 1e-9);  // still on the first block
    run.in.abort = false;
    run.stream.records.push_back(record(blocks[3], 2, 1));
    run.ticks(1000);
    EXPECT_EQ(run.samples.back().position, xyz(0, 0));
}

TEST(ComponentLogic, DisableStopsAtOnceAndDropsEverything) {
    Servo run;
    const std::vector<Block> blocks = diamond();
    for (std::uint32_t i = 0; i < blocks.size(); ++i) run.stream.records.push_back(record(blocks[i], 1, i + 1));
    run.ticks(100);
    const AxisVector at = run.samples.back().position;
    run.in.enable = false;
    run.ticks(50);
    EXPECT_EQ(run.out.mode, ComponentState::disabled);
    EXPECT_EQ(run.samples.back().position, at);
    EXPECT_TRUE(run.out.done);
    run.in.enable = true;
    run.ticks(500);
    EXPECT_EQ(run.samples.back().position, at);  // nothing of the old program resumes
}

TEST(ComponentLogic, ProgramIdsAndSeqsKeepAll64BitsThroughTheStream) {
    // Host ids are microseconds: two programs 2^32 us (71.6 min) apart share their low 32 bits.
    const std::uint64_t first = 0x0000'1234'8000'0001, second = first + (std::uint64_t{1} << 32);
    const std::uint64_t high_seq = (std::uint64_t{1} << 32) + 3;
    const stream::BlockRecord r = streamed(record(diamond()[0], second, high_seq));
    EXPECT_EQ(r.program, second);
    EXPECT_EQ(r.seq, high_seq);

    Servo run;
    const std::vector<Block> blocks = diamond();
    run.stream.records.push_back(streamed(record(blocks[0], first, 1)));
    run.ticks(700);
    ASSERT_EQ(run.out.mode, ComponentState::idle);
    // The next program, not a repeat of the first one's seq 1.
    run.stream.records.push_back(streamed(record(blocks[1], second, 1)));
    run.ticks(700);
    EXPECT_EQ(run.out.program, second);
    EXPECT_EQ(run.out.next_seq, 2u);
    EXPECT_EQ(run.out.rejected, 0u);
    EXPECT_EQ(run.samples.back().position, blocks[1].target);
}

// Drives off: the axes may be pushed by hand; the outputs follow them, so enabling moves nothing.
TEST(ComponentLogic, WhileDisabledTheOutputsFollowTheFeedbackAndEnablingMovesNothing) {
    Servo run;
    const std::vector<Block> blocks = diamond();
    for (std::uint32_t i = 0; i < blocks.size(); ++i) run.stream.records.push_back(record(blocks[i], 1, i + 1));
    run.ticks(300);
    run.in.enable = false;
    run.ideal_drive = false;
    run.in.velocity_feedback = AxisVector::Zero();  // the axes came to rest
    for (int k = 0; k < 100; ++k) {
        run.in.position_feedback = xyz(3.0 + 0.01 * k, -2.0, 0.5);
        run.ticks(1);
        ASSERT_EQ(run.samples.back().position, run.in.position_feedback);
        ASSERT_EQ(run.samples.back().velocity, AxisVector::Zero());
    }
    EXPECT_EQ(run.out.mode, ComponentState::disabled);
    run.in.enable = true;
    const AxisVector at = run.in.position_feedback;
    run.ticks(200);
    for (std::size_t k = run.samples.size() - 200; k < run.samples.size(); ++k) ASSERT_EQ(run.samples[k].position, at);
    EXPECT_EQ(run.out.mode, ComponentState::idle);
    // The interrupted program stays refused; a new one runs from where the axes are.
    run.stream.records.push_back(record(blocks[1], 1, 2));
    run.stream.records.push_back(record(blocks[0], 2, 1));
    run.ticks(1000);
    EXPECT_EQ(run.samples.back().position, blocks[0].target);
    EXPECT_EQ(run.out.program, 2u);
}

// Pin blocks with seq 0 carry no program: after a disable the enable's rise lets them run again
// (before, a disable refused every later seq-0 block for good).
TEST(ComponentLogic, PinBlocksRunAgainOnceEnableRises) {
    Servo run;
    run.in.enable = false;  // LinuxCNC starts with the machine off
    run.ticks(10);
    run.in.enable = true;
    run.in.strobe = true;
    run.in.pin_block.block = diamond()[0];
    run.ticks(700);
    EXPECT_EQ(run.samples.back().position, diamond()[0].target);
    EXPECT_EQ(run.out.rejected, 0u);
}

namespace {

ComponentSettings limited() {
    ComponentSettings s = settings();
    s.planner.limits = test::uniform_limits(250.0, 2000.0, 40000.0);
    return s;
}

// The component's first period finds the axes moving at `v` through `p` (it restarted).
void moving_at(Servo& run, const AxisVector& p, const AxisVector& v) {
    run.in.position_feedback = p;
    run.in.velocity_feedback = v;
}

}  // namespace

TEST(ComponentLogic, StartingWhileTheAxesMoveBrakesFromTheFeedbackWithinTheLimits) {
    const AxisVector p = xyz(40.0, -12.0, 3.0), v = xyz(120.0, -80.0, 0.0);
    Servo run(limited());
    moving_at(run, p, v);
    run.stream.records.push_back(record(diamond()[0], 9, 1));  // a block sent meanwhile is refused
    run.ticks(1);
    EXPECT_LT((run.samples[0].position - p).cwiseAbs().maxCoeff(), 1e-12);  // no jump
    EXPECT_LT((run.samples[0].velocity - v).cwiseAbs().maxCoeff(), 1e-9);   // nor a velocity step
    EXPECT_EQ(run.out.mode, ComponentState::aborting);
    EXPECT_EQ(run.out.error, ComponentError::stopped_from_feedback);
    run.ticks(400);
    const FirChain chain(settings().planner.filters);
    EXPECT_EQ(run.samples.back().position, braking_rest(chain, p, v));
    EXPECT_EQ(run.samples.back().velocity, AxisVector::Zero());
    EXPECT_EQ(run.out.mode, ComponentState::error);
    EXPECT_EQ(run.out.rejected, 1u);
    EXPECT_LE(test::worst_ratio(run.samples, limited().planner.limits), 1.0);
    std::size_t stop_ticks = 0;
    while (run.samples[stop_ticks].velocity != AxisVector::Zero()) ++stop_ticks;
    // The next program plans from the rest position.
    Block next = diamond()[1];
    run.stream.records.push_back(record(next, 10, 1));
    run.ticks(1500);
    EXPECT_EQ(run.samples.back().position, next.target);
    EXPECT_EQ(run.out.mode, ComponentState::idle);
    EXPECT_EQ(run.out.error, ComponentError::none);
    EXPECT_LE(test::worst_ratio(run.samples, limited().planner.limits), 1.0);
    std::printf("braked from 144 mm/s in %.3f s (Td %.3f s), %.2f mm on\n", 0.001 * static_cast<double>(stop_ticks),
                chain.delay(), (braking_rest(chain, p, v) - p).norm());
}

// Faster than the machine can stop through the chain: the share that it can stop, within limits.
TEST(ComponentLogic, TooFastAFeedbackVelocityIsBrakedFromTheShareTheLimitsAllow) {
    const AxisVector p = xyz(0.0, 0.0, 0.0), v = xyz(400.0, 0.0, 0.0);  // max_velocity 250
    Servo run(limited());
    moving_at(run, p, v);
    run.ticks(400);
    const std::vector<AxisState>& samples = run.samples;
    EXPECT_NEAR(samples[0].velocity[0], 250.0, 1e-9);
    EXPECT_LE(test::worst_ratio(samples, limited().planner.limits), 1.0);
    EXPECT_EQ(samples.back().velocity, AxisVector::Zero());
}

// Encoder noise below brake_speed: a start at rest, exactly on the feedback.
TEST(ComponentLogic, FeedbackSlowerThanTheBrakeSpeedStartsAtRest) {
    const AxisVector p = xyz(1.25, 2.5, -3.75);
    Servo run(limited());
    moving_at(run, p, xyz(0.9, -0.9, 0.0));
    run.ideal_drive = false;
    run.ticks(50);
    for (const AxisState& s : run.samples) ASSERT_EQ(s.position, p);
    EXPECT_EQ(run.out.mode, ComponentState::idle);
    EXPECT_EQ(run.out.error, ComponentError::none);
}

namespace {

// examples/linuxcnc/configs/firtp_hal's machine: every move smoothed at the axes' limits.
ComponentSettings linuxcnc_sample_settings() {
    ComponentSettings s;
    s.planner.fixed_chain = false;
    s.planner.period = 0.001;
    s.planner.max_rate = 1.2;
    s.planner.limits.axes = 3;
    for (int a = 0; a < 3; ++a) s.planner.limits.axis[a] = {300.0, 5000.0, 100000.0};
    s.default_tolerance = 0.05;
    return s;
}

// The start of examples/arcs.ngc as `firtp host` sends it: up, down, along X, a quarter circle in
// 0.28 mm chords (G3 X30 Y10 I0 J10 at F2400).
std::vector<Block> arcs_start() {
    std::vector<Block> blocks;
    auto add = [&](AxisVector target, double feed, MotionType type, std::int64_t line) {
        Block b;
        b.target = target;
        b.feed = feed;
        b.type = type;
        b.tolerance = 0.02;
        b.line = line;
        blocks.push_back(b);
    };
    add(xyz(0, 0, 1), 300, MotionType::traverse, 4);
    add(xyz(0, 0, 0), 5, MotionType::feed, 5);
    add(xyz(20, 0, 0), 40, MotionType::feed, 7);
    const double pi = 3.14159265358979323846;
    for (int i = 1; i <= 56; ++i) {
        const double angle = -0.5 * pi + 0.5 * pi * i / 56;
        add(xyz(20 + 10 * std::cos(angle), 10 + 10 * std::sin(angle), 0), 40, MotionType::feed, 8);
    }
    return blocks;
}

}  // namespace

// LinuxCNC enables firtp.so at "machine on", some hundred periods after its start; `firtp replay`
// enables it at once (the log does not say when). With the blocks taken in the same period, the
// trajectory is the same to the last bit, whenever enable rose: the planner's clock runs on while
// disabled (before, its times counted only enabled periods and the rounding moved with them).
TEST(ComponentLogic, TheTrajectoryDoesNotDependOnWhenTheMachineWasSwitchedOn) {
    const int blocks_at = 850, periods = 6000;
    const std::vector<Block> blocks = arcs_start();
    auto run = [&](int enable_at) {
        Servo s(linuxcnc_sample_settings());
        s.in.enable = false;
        s.ticks(enable_at);
        s.in.enable = true;
        s.ticks(blocks_at - enable_at);
        for (std::uint32_t i = 0; i < blocks.size(); ++i) s.stream.records.push_back(record(blocks[i], 3, i + 1));
        s.ticks(periods);
        EXPECT_EQ(s.out.mode, ComponentState::idle) << "enabled at " << enable_at;
        return std::vector<AxisState>(s.samples.begin() + blocks_at, s.samples.end());
    };
    const std::vector<AxisState> at_once = run(0);
    ASSERT_EQ(at_once.back().position, blocks.back().target);
    for (int enable_at : {1, 5, 137, 300, 333, 700}) {
        const std::vector<AxisState> later = run(enable_at);
        for (std::size_t k = 0; k < at_once.size(); ++k) {
            ASSERT_EQ(later[k].position, at_once[k].position) << "enabled at " << enable_at << ", period " << blocks_at + k;
            ASSERT_EQ(later[k].velocity, at_once[k].velocity) << "enabled at " << enable_at << ", period " << blocks_at + k;
            ASSERT_EQ(later[k].acceleration, at_once[k].acceleration) << "enabled at " << enable_at << ", period " << blocks_at + k;
        }
    }
}
