#include "gcode_test_support.hpp"

#include <firtp/gcode.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {

using firtp::AxisVector;
using firtp::Block;
using firtp::MachineConfig;
using firtp::MotionType;
using firtp::Termination;

constexpr double inf = std::numeric_limits<double>::infinity();

using firtp::test::parse;

AxisVector xyz(double x, double y, double z = 0.0) {
    AxisVector v = AxisVector::Zero();
    v << x, y, z, 0, 0, 0, 0, 0, 0;
    return v;
}

void expect_target(const Block& b, const AxisVector& expected) {
    EXPECT_LT((b.target - expected).norm(), 1e-12) << "target " << b.target.transpose() << " at line " << b.line;
}

TEST(Gcode, Corner90Case) {
    const firtp::Program p = firtp::read_gcode(FIRTP_PROGRAM_DATA "/corner90.ngc", firtp::default_machine());
    EXPECT_EQ(p.file, FIRTP_PROGRAM_DATA "/corner90.ngc");
    EXPECT_EQ(p.start, AxisVector::Zero());
    ASSERT_EQ(p.blocks.size(), 2u);
    expect_target(p.blocks[0], xyz(2.5, 0));
    expect_target(p.blocks[1], xyz(2.5, 2.5));
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_DOUBLE_EQ(p.blocks[i].feed, 50.0);
        EXPECT_DOUBLE_EQ(p.blocks[i].tolerance, 0.1);
        EXPECT_EQ(p.blocks[i].termination, Termination::blend);
        EXPECT_EQ(p.blocks[i].type, MotionType::feed);
        EXPECT_EQ(p.blocks[i].line, static_cast<std::int64_t>(i) + 5);
    }
}

TEST(Gcode, DiamondCase) {
    const firtp::Program p = firtp::read_gcode(FIRTP_PROGRAM_DATA "/diamond.ngc", firtp::default_machine());
    ASSERT_EQ(p.blocks.size(), 4u);
    expect_target(p.blocks[0], xyz(25, 25));
    expect_target(p.blocks[1], xyz(50, 0));
    expect_target(p.blocks[2], xyz(25, -25));
    expect_target(p.blocks[3], xyz(0, 0));
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_DOUBLE_EQ(p.blocks[i].feed, 250.0);  // under the 300 / cos 45 deg cap
        EXPECT_DOUBLE_EQ(p.blocks[i].tolerance, 0.5);
        EXPECT_EQ(p.blocks[i].type, MotionType::feed);
        EXPECT_EQ(p.blocks[i].line, static_cast<std::int64_t>(i) + 5);
    }
}

TEST(Gcode, IncrementalMovesFromStartKeepOtherAxes) {
    AxisVector start = xyz(1, 1, 1);
    start[3] = 5.0;  // A
    const firtp::Program p = parse("G91 G1 F600 X1 Y2\nX1\nG90 X0\n", firtp::default_machine(), start);
    EXPECT_EQ(p.start, start);
    ASSERT_EQ(p.blocks.size(), 3u);
    AxisVector a = xyz(2, 3, 1), b = xyz(3, 3, 1), c = xyz(0, 3, 1);
    a[3] = b[3] = c[3] = 5.0;
    expect_target(p.blocks[0], a);
    expect_target(p.blocks[1], b);
    expect_target(p.blocks[2], c);
}

TEST(Gcode, InchUnitsConvertToMm) {
    const firtp::Program p = parse("G20\nG1 F10 X1 Y-0.5\nG64 P0.01 X2\nG91 Z.1\nG21 G90 X3\n");
    ASSERT_EQ(p.blocks.size(), 4u);
    expect_target(p.blocks[0], xyz(25.4, -12.7));
    expect_target(p.blocks[1], xyz(50.8, -12.7));
    expect_target(p.blocks[2], xyz(50.8, -12.7, 2.54));
    expect_target(p.blocks[3], xyz(3, -12.7, 2.54));
    EXPECT_DOUBLE_EQ(p.blocks[0].feed, 254.0 / 60.0);
    EXPECT_DOUBLE_EQ(p.blocks[0].tolerance, 0.05);
    EXPECT_DOUBLE_EQ(p.blocks[1].tolerance, 0.254);
    EXPECT_DOUBLE_EQ(p.blocks[3].feed, 254.0 / 60.0);  // the feed keeps its speed across G21, as in LinuxCNC
}

TEST(Gcode, FeedOnTheG20LineUsesThePreviousUnits) {
    // LinuxCNC sets F before it changes units on the same line.
    const firtp::Program p = parse("G20 F600 G1 X1\nF10 X2\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_DOUBLE_EQ(p.blocks[0].feed, 10.0);
    EXPECT_DOUBLE_EQ(p.blocks[1].feed, 254.0 / 60.0);
}

TEST(Gcode, FeedIsCappedByAxisVelocities) {
    MachineConfig m = firtp::default_machine();
    m.limits.axis[0].max_velocity = 100.0;
    m.limits.axis[1].max_velocity = 50.0;
    m.limits.axis[2].max_velocity = 0.0;  // not limited
    const firtp::Program p = parse("G1 F60000 X10\nY10\nX20 Y20\nZ5\nF600 X30\n", m);
    ASSERT_EQ(p.blocks.size(), 5u);
    EXPECT_DOUBLE_EQ(p.blocks[0].feed, 100.0);
    EXPECT_DOUBLE_EQ(p.blocks[1].feed, 50.0);
    EXPECT_NEAR(p.blocks[2].feed, 50.0 * std::sqrt(2.0), 1e-9);  // Y's share of the diagonal limits it
    EXPECT_DOUBLE_EQ(p.blocks[3].feed, 1000.0);
    EXPECT_DOUBLE_EQ(p.blocks[4].feed, 10.0);

    m.limits.max_linear_velocity = 60.0;
    const firtp::Program q = parse("G1 F60000 X10\nY10\nX20 Y20\nZ5\n", m);
    EXPECT_DOUBLE_EQ(q.blocks[0].feed, 60.0);
    EXPECT_DOUBLE_EQ(q.blocks[1].feed, 50.0);
    EXPECT_DOUBLE_EQ(q.blocks[2].feed, 60.0);
    EXPECT_DOUBLE_EQ(q.blocks[3].feed, 60.0);
}

TEST(Gcode, RapidRunsAtTheMachineSpeedAlongTheMove) {
    const firtp::Program p = parse("G0 X3 Y4\nX0 Y0 Z-1\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_EQ(p.blocks[0].type, MotionType::traverse);
    EXPECT_DOUBLE_EQ(p.blocks[0].feed, 375.0);  // Y at 300 mm/s covers 4/5 of the path
    EXPECT_NEAR(p.blocks[1].feed, 300.0 * std::sqrt(26.0) / 4.0, 1e-9);

    MachineConfig m = firtp::default_machine();
    m.limits.max_linear_velocity = 200.0;
    EXPECT_DOUBLE_EQ(parse("G0 X3 Y4\n", m).blocks[0].feed, 200.0);
}

TEST(Gcode, ExactStopAndTolerances) {
    const firtp::Program p = parse("G61\nG1 F600 X1\nG61.1 X2\nG64 X3\nG64 P0.2 X4\nG64 P0 X5\nG61 G0 X6\n");
    ASSERT_EQ(p.blocks.size(), 6u);
    EXPECT_EQ(p.blocks[0].termination, Termination::exact_stop);
    EXPECT_EQ(p.blocks[0].tolerance, 0.0);
    EXPECT_EQ(p.blocks[1].termination, Termination::exact_stop);
    EXPECT_EQ(p.blocks[2].termination, Termination::blend);
    EXPECT_DOUBLE_EQ(p.blocks[2].tolerance, 0.05);  // machine default
    EXPECT_DOUBLE_EQ(p.blocks[3].tolerance, 0.2);
    // LinuxCNC's canon reports G64 P0 as it reports G64: the machine's tolerance (not none).
    EXPECT_DOUBLE_EQ(p.blocks[4].tolerance, 0.05);
    EXPECT_EQ(p.blocks[4].termination, Termination::blend);
    EXPECT_EQ(p.blocks[5].termination, Termination::exact_stop);
    EXPECT_EQ(p.blocks[5].type, MotionType::traverse);
}

TEST(Gcode, StartsBlendingWithTheMachineTolerance) {
    MachineConfig m = firtp::default_machine();
    m.default_tolerance = 0.3;
    const firtp::Program p = parse("G1 F60 X1\n", m);
    EXPECT_EQ(p.blocks[0].termination, Termination::blend);
    EXPECT_EQ(p.blocks[0].tolerance, 0.3);
}

TEST(Gcode, ModalMotionAndLinesWithoutAxes) {
    const firtp::Program p = parse("G0\nG1 F60\nG0 X1\n\nY2\nG1 X0\nY0\nG17 G90 G21\n");
    ASSERT_EQ(p.blocks.size(), 4u);
    EXPECT_EQ(p.blocks[0].type, MotionType::traverse);
    EXPECT_EQ(p.blocks[1].type, MotionType::traverse);
    EXPECT_EQ(p.blocks[2].type, MotionType::feed);
    EXPECT_EQ(p.blocks[3].type, MotionType::feed);
    EXPECT_EQ(p.blocks[0].line, 3);
    EXPECT_EQ(p.blocks[1].line, 5);
    EXPECT_EQ(p.blocks[3].line, 7);
}

TEST(Gcode, ZeroLengthMovesAreDropped) {
    const firtp::Program p = parse("G1 F60 X0 Y0\nX1\nX1\nG91 X0\nG90 X2\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_EQ(p.blocks[0].line, 2);
    EXPECT_EQ(p.blocks[1].line, 5);
}

TEST(Gcode, BlanksInsideWordsAndNumbers) {
    const firtp::Program p = parse("g 0 1 f 6 0 0 x 1 . 5\ty - 2\n\tN 20 G1 X + . 5 Y 3 .\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    expect_target(p.blocks[0], xyz(1.5, -2));
    expect_target(p.blocks[1], xyz(0.5, 3));
    EXPECT_DOUBLE_EQ(p.blocks[0].feed, 10.0);
}

TEST(Gcode, CommentsAreSkipped) {
    const firtp::Program p =
        parse("(program: test; with G1 X9)\nG1 F60 (feed) X1 ; X7 (ignored\n(only a comment)\n;G1 X8\nX2(;)Y1\r\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    expect_target(p.blocks[0], xyz(1, 0));
    expect_target(p.blocks[1], xyz(2, 1));
    EXPECT_EQ(p.blocks[1].line, 5);
}

TEST(Gcode, PercentLinesDelimitTheProgram) {
    const firtp::Program p = firtp::parse_gcode("%\nG1 F60 X1\n%\nG1 X99\nnot G-code at all\n", "t.ngc",
                                                firtp::default_machine());
    ASSERT_EQ(p.blocks.size(), 1u);
    expect_target(p.blocks[0], xyz(1, 0));
    EXPECT_EQ(p.blocks[0].line, 2);
}

TEST(Gcode, LinesAfterProgramEndAreIgnored) {
    const firtp::Program m2 = parse("G1 F60 X1 M2\nG1 X2\n@@ nonsense\n");
    ASSERT_EQ(m2.blocks.size(), 1u);
    const firtp::Program m30 = parse("G1 F60 X1\nm30\nX2\n");
    ASSERT_EQ(m30.blocks.size(), 1u);
    const firtp::Program after = parse("G1 F60\nM2 X5\nX6\n");  // words after M2 on its line still run
    ASSERT_EQ(after.blocks.size(), 1u);
    expect_target(after.blocks[0], xyz(5, 0));
}

TEST(Gcode, EmptyProgram) {
    EXPECT_TRUE(parse("").blocks.empty());
    EXPECT_TRUE(firtp::parse_gcode("%\n(nothing)\n%\n", "t.ngc", firtp::default_machine()).blocks.empty());
    // LinuxCNC: a '%' opens the program only on its first line.
    EXPECT_EQ(firtp::test::parse_error("\n(nothing)\n%\n"), "t.ngc:3: Bad character '%' used");
}

}  // namespace

// LinuxCNC 2.9's interpreter runs (py,...), (pyrun,...) and (pyreload) comments in its Python
// plugin, which crashes on them: a null dereference on text that is not UTF-8, a heap read past a
// buffer on a syntax error (both found by fuzz.gcode). firtp refuses them with their place; other
// comments, in any encoding and beginning with "py" as a word, still read.
TEST(Gcode, PythonCommentsAreRefused) {
    const MachineConfig m = firtp::default_machine();
    for (const char* program : {"G21\n( pyrun,x = '\xff\xfe')\nG1 X1 F600\nM2\n", "G21\n( PyRun,a CAM note, not Python)\nG1 X1 F600\nM2\n",
                                "G21\n( py,x = 1)\nG1 X1 F600\nM2\n"}) {
        try {
            firtp::parse_gcode(program, "p.ngc", m);
            FAIL() << "no error: " << program;
        } catch (const firtp::GcodeError& e) {
            EXPECT_EQ(e.line(), 2) << program;
            EXPECT_EQ(e.column(), 3) << program;
            EXPECT_NE(std::string(e.what()).find("firtp does not run Python"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(firtp::parse_gcode("(H\xf6he in Latin-1)\n(pyramid pocket)\nG1 X1 F600\nM2\n", "p.ngc", m).blocks.size(), 1u);
}
