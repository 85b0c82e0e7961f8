// What LinuxCNC's interpreter reports beside moves, as firtp records it: non-motion events in
// program order with file and line, waits, work and tool offsets, feed modes, refusals.
#include "gcode_test_support.hpp"

#include <firtp/gcode.hpp>
#include <firtp/ini.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using firtp::EventKind;
using firtp::Program;
using firtp::Termination;
using firtp::test::at;
using firtp::test::parse;
using firtp::test::parse_error;

TEST(Rs274Events, InProgramOrderBetweenBlocksWithTheirLines) {
    const Program p = firtp::parse_gcode(
        "G21 G90\nT2 M6\nS5000 M3\nG1 F600 X10\nM8\nG4 P1.5\nG1 X20\nM0\nG1 Y5\nM1\nG1 Y10\nM9\nM5\nM2\n", "part.ngc",
        firtp::default_machine());
    struct Expected {
        EventKind kind;
        double value;
        std::size_t before;
        int line;
    };
    const std::vector<Expected> expected{
        {EventKind::tool_select, 2, 0, 2},       {EventKind::tool_change, 2, 0, 2},
        {EventKind::spindle_speed, 5000, 0, 3},  {EventKind::spindle_clockwise, 5000, 0, 3},
        {EventKind::flood_on, 0, 1, 5},          {EventKind::dwell, 1.5, 1, 6},
        {EventKind::pause, 0, 2, 8},             {EventKind::optional_pause, 0, 3, 10},
        {EventKind::coolant_off, 0, 4, 12},      {EventKind::spindle_stop, 0, 4, 13},
        {EventKind::program_end, 0, 4, 14}};
    ASSERT_EQ(p.blocks.size(), 4u);
    ASSERT_EQ(p.events.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const firtp::ProgramEvent& e = p.events[i];
        EXPECT_EQ(e.kind, expected[i].kind) << i << ": " << firtp::event_name(e.kind);
        EXPECT_DOUBLE_EQ(e.value, expected[i].value) << i;
        EXPECT_EQ(e.before_block, expected[i].before) << i;
        EXPECT_EQ(e.line, expected[i].line) << i;
        EXPECT_EQ(e.file, "part.ngc") << i;
    }
    // Motion stops before the coolant and the dwell (block 0), the pauses (1, 2). After the last
    // block (3) nothing is marked: the end stops it, and firtp_tp sees its queue end there too.
    EXPECT_EQ(p.blocks[0].termination, Termination::exact_stop);
    EXPECT_EQ(p.blocks[1].termination, Termination::exact_stop);
    EXPECT_EQ(p.blocks[2].termination, Termination::exact_stop);
    EXPECT_EQ(p.blocks[3].termination, Termination::blend);
}

// LinuxCNC 2.9's task executes these only once motion has finished (emcTaskCheckPreconditions):
// the block before each ends in an exact stop. A T word (the tool changer prepares), an output
// synchronised with motion (M62) and an offset of a coordinate system not in use do not wait.
TEST(Rs274Events, MotionWaitsWhereLinuxCNCsTaskWaits) {
    struct Case {
        const char* between;
        bool waits;
    };
    for (const Case& c : {Case{"M8", true}, Case{"M7", true}, Case{"M9", true}, Case{"M5", true}, Case{"S2000", true},
                          Case{"M3 S1000", true}, Case{"(MSG, check the clamp)", true}, Case{"G92 X0", true},
                          Case{"G10 L2 P1 X1", true}, Case{"G10 L2 P2 X1", false}, Case{"G54", false}, Case{"G55", true},
                          Case{"M64 P0", true}, Case{"M66 P0 L0", true}, Case{"T3", false}, Case{"M62 P0", false},
                          Case{"F300", false}}) {
        const Program p = parse(std::string("G64 P0.01 Q0\nG1 F600 X10\n") + c.between + "\nG1 X20 Y5\n");
        SCOPED_TRACE(c.between);
        ASSERT_EQ(p.blocks.size(), 2u);
        EXPECT_EQ(p.blocks[0].termination, c.waits ? Termination::exact_stop : Termination::blend);
        EXPECT_EQ(p.blocks[1].termination, Termination::blend);  // the last: nothing after it marks it
    }
}

TEST(Rs274Events, WorkOffsetsG92AndUnitsGiveMachineCoordinates) {
    const Program g54 = parse("G10 L2 P1 X5 Y6 Z7\nG54 G0 X1 Y1 Z1\nG55 G0 X1 Y1 Z1\n");
    ASSERT_EQ(g54.blocks.size(), 2u);
    EXPECT_LT((g54.blocks[0].target - at({{'X', 6}, {'Y', 7}, {'Z', 8}})).norm(), 1e-12);
    EXPECT_LT((g54.blocks[1].target - at({{'X', 1}, {'Y', 1}, {'Z', 1}})).norm(), 1e-12);  // G55 unset: zero
    const Program g92 = parse("G0 X10\nG92 X0\nG1 F600 X1\nG92.1\nG1 X2\n");
    ASSERT_EQ(g92.blocks.size(), 3u);
    EXPECT_NEAR(g92.blocks[1].target[0], 11.0, 1e-12);
    EXPECT_NEAR(g92.blocks[2].target[0], 2.0, 1e-12);
    const Program inch = parse("G20 G0 X1\nG10 L2 P1 X1\nG0 X1\n");
    EXPECT_NEAR(inch.blocks[0].target[0], 25.4, 1e-9);
    EXPECT_NEAR(inch.blocks[1].target[0], 50.8, 1e-9);
}

TEST(Rs274Events, ToolLengthAndParametersFromTheIni) {
    firtp::MachineConfig m = firtp::load_machine(firtp::IniFile::read(FIRTP_PROGRAM_DATA "/cam/cam.ini"));
    // cam.var: G54 = X10 Y-5 Z2; cam.tbl: T1 Z25.
    const Program p = parse("T1 M6\nG43 H1\nG54 G0 X0 Y0 Z0\nG49 G0 Z0\n", m);
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_LT((p.blocks[0].target - at({{'X', 10}, {'Y', -5}, {'Z', 27}})).norm(), 1e-9);
    EXPECT_LT((p.blocks[1].target - at({{'X', 10}, {'Y', -5}, {'Z', 2}})).norm(), 1e-9);
    EXPECT_EQ(parse_error("T5 M6\n", m), "t.ngc:1: Requested tool 5 not found in the tool table");
}

TEST(Rs274Events, StartupCodeRunsBeforeTheProgram) {
    firtp::MachineConfig m = firtp::default_machine();
    m.startup_code = "G20 G91";  // as [RS274NGC]RS274NGC_STARTUP_CODE
    const Program p = parse("G0 X1\nX1\n", m);
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_NEAR(p.blocks[1].target[0], 50.8, 1e-9);
    m.startup_code = "G5";
    m.ini_file = "machine.ini";
    EXPECT_EQ(parse_error("G0 X1\n", m),
              "machine.ini:0: [RS274NGC]RS274NGC_STARTUP_CODE 'G5': All axes missing with motion code");
}

TEST(Rs274Events, FeedPerRevolutionAndInverseTime) {
    const Program rev = parse("S1000 M3\nG95 G1 F0.1 X10\n");  // 0.1 mm/rev at 1000 rpm: 100 mm/min
    ASSERT_EQ(rev.blocks.size(), 1u);
    EXPECT_NEAR(rev.blocks[0].feed, 100.0 / 60.0, 1e-12);
    const Program inverse = parse("G93 G1 F6 X10\n");  // 1/6 min for 10 mm
    ASSERT_EQ(inverse.blocks.size(), 1u);
    EXPECT_NEAR(inverse.blocks[0].feed, 1.0, 1e-9);
}

TEST(Rs274Events, LoopsAndCannedCyclesExpand) {
    const Program p = parse("#1=0\no10 while [#1 lt 3]\nG1 F600 X[#1+1]\n#1=[#1+1]\no10 endwhile\n"
                            "G0 Z5\nG98 G81 X20 Y0 Z-2 R1 F100\nX30\nG80\n");
    // 3 loop moves, the rapid up, then per hole: traverse over it, down to R, feed to Z, back up (G98).
    ASSERT_EQ(p.blocks.size(), 3u + 1u + 2u * 4u);
    EXPECT_NEAR(p.blocks[6].target[2], -2.0, 1e-12);
    EXPECT_EQ(p.blocks[6].type, firtp::MotionType::feed);
    EXPECT_NEAR(p.blocks[7].target[2], 5.0, 1e-12);
    EXPECT_EQ(p.blocks[2].line, 3);
    EXPECT_NEAR(p.blocks[2].target[0], 3.0, 1e-12);
}

TEST(Rs274Events, RefusalsNameFileLineAndLinuxCncsReason) {
    EXPECT_EQ(parse_error("G1 F100 X1\nG2 X2 Y0 R0.1\n"), "t.ngc:2: Arc radius too small to reach end point");
    EXPECT_EQ(parse_error("G1 F100 X1\nG1 X2 Q\n"), "t.ngc:2: No characters found in reading real value");
    EXPECT_EQ(parse_error("G1 X2\n"), "t.ngc:1: Cannot do g1 with zero feed rate");
    EXPECT_EQ(parse_error("G38.2 F10 Z-1\n"), "t.ngc:1: probing (G38): firtp cannot plan it");
    EXPECT_EQ(firtp::test::parse_error("G1 F100 X1\n").substr(0, 6), "no err");
    try {
        firtp::parse_gcode("G1 F100 X1\n", "nofinish.ngc", firtp::default_machine());
        FAIL() << "no error";
    } catch (const firtp::GcodeError& e) {
        EXPECT_STREQ(e.what(), "nofinish.ngc:1: File ended with no percent sign or program end");
        EXPECT_EQ(e.line(), 1);  // the last line the interpreter read
    }
}

// An O-word loop that never moves runs forever in LinuxCNC; here it is refused at its line once more
// lines ran without a move than the program may have blocks.
TEST(Rs274Events, EndlessLoopWithoutMotionIsRefused) {
    firtp::MachineConfig m = firtp::default_machine();
    m.max_program_blocks = 5000;
    try {
        firtp::parse_gcode("G1 F100 X1\n#1 = 0\no100 while [1]\n#1 = [#1 + 1]\no100 endwhile\nM2\n", "loop.ngc", m);
        FAIL() << "no error";
    } catch (const firtp::GcodeError& e) {
        EXPECT_EQ(std::string(e.what()).find("loop.ngc:"), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("lines ran without a move: an endless loop?"), std::string::npos) << e.what();
        EXPECT_GE(e.line(), 3);
        EXPECT_LE(e.line(), 5);
    }
    // A loop that moves on every pass is a program, however long.
    const firtp::Program p = firtp::parse_gcode("G1 F100 X0\n#1 = 0\no100 while [#1 LT 3000]\nG1 X[#1 MOD 2 + 1]\n#1 = [#1 + 1]\no100 endwhile\nM2\n", "moves.ngc", m);
    EXPECT_GE(p.blocks.size(), 3000u);
}

}  // namespace
