// Nine axes: A B C (degrees) and U V W words, LinuxCNC's feed rule and the axis velocity limits.
#include "gcode_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using firtp::MachineConfig;
using firtp::MotionType;
using firtp::Program;
using firtp::test::at;
using firtp::test::durations;
using firtp::test::nine_axis_machine;
using firtp::test::parse;
using firtp::test::parse_error;

double seconds(const Program& p) {
    EXPECT_EQ(p.blocks.size(), 1u);
    return durations(p).at(0);
}

TEST(GcodeAxes, FeedAppliesToXyzWhenTheyMove) {
    const Program p = parse("G1 F600 X30 Y40 A90\n", nine_axis_machine());
    ASSERT_EQ(p.blocks.size(), 1u);
    EXPECT_EQ(p.blocks[0].target, at({{'X', 30.0}, {'Y', 40.0}, {'A', 90.0}}));
    EXPECT_NEAR(seconds(p), 5.0, 1e-12);  // 50 mm at 10 mm/s; A rides along
    EXPECT_NEAR(p.blocks[0].feed, std::sqrt(50.0 * 50.0 + 90.0 * 90.0) / 5.0, 1e-12);
    EXPECT_NEAR(seconds(parse("G1 F600 X30 U100 W7\n", nine_axis_machine())), 3.0, 1e-12);
    EXPECT_NEAR(seconds(parse("G1 F600 Z-30 B45 V1\n", nine_axis_machine())), 3.0, 1e-12);
}

TEST(GcodeAxes, FeedAppliesToUvwWhenOnlyTheyAndRotariesMove) {
    const Program p = parse("G1 F600 U30 V40\n", nine_axis_machine());
    EXPECT_NEAR(seconds(p), 5.0, 1e-12);
    EXPECT_DOUBLE_EQ(p.blocks[0].feed, 10.0);
    EXPECT_NEAR(seconds(parse("G1 F600 U30 A90\n", nine_axis_machine())), 3.0, 1e-12);

    const Program inch = parse("G20\nG1 F60 U1\n", nine_axis_machine());
    EXPECT_EQ(inch.blocks[0].target, at({{'U', 25.4}}));
    EXPECT_NEAR(seconds(inch), 1.0, 1e-12);
}

TEST(GcodeAxes, RotaryAloneFeedsInDegreesPerMinute) {
    const Program p = parse("G1 F3600 A90\n", nine_axis_machine());
    EXPECT_DOUBLE_EQ(p.blocks[0].feed, 60.0);
    EXPECT_NEAR(seconds(p), 1.5, 1e-12);
    EXPECT_NEAR(seconds(parse("G1 F600 B30 C40\n", nine_axis_machine())), 5.0, 1e-12);

    // G20 scales neither the angles nor a feed in degrees per minute.
    const Program inch = parse("G20\nG1 F3600 A90\nF10 X1 A180\n", nine_axis_machine());
    ASSERT_EQ(inch.blocks.size(), 2u);
    EXPECT_EQ(inch.blocks[0].target, at({{'A', 90.0}}));
    EXPECT_DOUBLE_EQ(inch.blocks[0].feed, 60.0);
    EXPECT_EQ(inch.blocks[1].target, at({{'X', 25.4}, {'A', 180.0}}));
    EXPECT_NEAR(durations(inch)[1], 6.0, 1e-12);  // 1 in at 10 in/min
}

TEST(GcodeAxes, IncrementalAndEmptyMoves) {
    const Program p = parse("G91 G1 F600 A10\nA10 W-1\nA0\nG20 C1\n", nine_axis_machine());
    ASSERT_EQ(p.blocks.size(), 3u);
    // The interpreter adds increments to its position (program units): equal to rounding.
    EXPECT_LT((p.blocks[1].target - at({{'A', 20.0}, {'W', -1.0}})).norm(), 1e-12);
    EXPECT_LT((p.blocks[2].target - at({{'A', 20.0}, {'C', 1.0}, {'W', -1.0}})).norm(), 1e-12);
    EXPECT_TRUE(parse("G1 F600 A0 U0\n", nine_axis_machine()).blocks.empty());
}

TEST(GcodeAxes, AxisVelocityLimitsLengthenTheMove) {
    MachineConfig m = nine_axis_machine();
    m.limits.axis[3].max_velocity = 10.0;  // A: 10 deg/s
    const Program p = parse("G1 F600 X30 A90\n", m);
    EXPECT_NEAR(seconds(p), 9.0, 1e-12);  // not 3 s: A needs 9
    EXPECT_NEAR(seconds(parse("G1 F3600 A90\n", m)), 9.0, 1e-12);
    EXPECT_NEAR(seconds(parse("G1 F600 U30 A-90\n", m)), 9.0, 1e-12);

    const Program rapid = parse("G0 X30 A90\n", m);
    EXPECT_EQ(rapid.blocks[0].type, MotionType::traverse);
    EXPECT_NEAR(seconds(rapid), 9.0, 1e-12);
    EXPECT_NEAR(seconds(parse("G0 X3 Y4 B600\n", nine_axis_machine())), 2.0, 1e-12);  // B at 300 deg/s
    EXPECT_NEAR(seconds(parse("G0 X3 Y4\n", nine_axis_machine())), 4.0 / 300.0, 1e-12);
}

TEST(GcodeAxes, MaxLinearVelocityLimitsAllButRotaryOnlyMoves) {
    MachineConfig m = nine_axis_machine();
    m.limits.max_linear_velocity = 5.0;
    EXPECT_NEAR(seconds(parse("G1 F600 X30 A9\n", m)), 6.0, 1e-12);
    EXPECT_NEAR(seconds(parse("G1 F600 U30\n", m)), 6.0, 1e-12);  // the speed along U V W, as LinuxCNC's vLimit
    EXPECT_NEAR(seconds(parse("G1 F3600 A90\n", m)), 1.5, 1e-12);
    EXPECT_NEAR(seconds(parse("G0 X30 A90\n", m)), 6.0, 1e-12);
    EXPECT_NEAR(seconds(parse("G0 A90\n", m)), 0.3, 1e-12);
}

TEST(GcodeAxes, RapidOfAnUnlimitedRotary) {
    MachineConfig m = nine_axis_machine();
    m.limits.axis[3].max_velocity = 0.0;  // A not limited
    m.limits.max_linear_velocity = 100.0;
    EXPECT_EQ(parse_error("G0 X1\nG0 A90", m),
              "t.ngc:2: G0 needs the axes' MAX_VELOCITY: this machine has no rapid speed");
    EXPECT_EQ(parse_error("G0 X1 A90", m), "no error");  // X and the linear limit time it
}

TEST(GcodeAxes, AxesBeyondTheMachineAreRejected) {
    MachineConfig m = firtp::default_machine();
    m.limits.axes = 6;
    EXPECT_EQ(parse_error("G1 F60 C1\nG1 U1", m), "t.ngc:2: Bad character 'u' used");  // LinuxCNC's words
    EXPECT_EQ(parse_error("G0 X1 Y2 Z3 A4 B5 C6", m), "no error");  // X Y Z time it; A B C are not limited
    EXPECT_EQ(parse_error("G0 C6", m), "t.ngc:1: G0 needs the axes' MAX_VELOCITY: this machine has no rapid speed");
}

}  // namespace
