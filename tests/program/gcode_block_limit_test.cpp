// [FIRTP]MAX_PROGRAM_BLOCKS: the program is kept whole in memory and one short arc line can
// become up to 10^6 chord blocks, so the blocks a program expands to are bounded; the line that
// goes beyond is named before its blocks are made.
#include "gcode_test_support.hpp"
#include "machine_test_support.hpp"

#include <firtp/gcode.hpp>
#include <firtp/ini.hpp>
#include <firtp/machine.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

using firtp::test::load_error;
using firtp::test::parse;
using firtp::test::parse_error;

firtp::MachineConfig machine_with(const std::string& firtp_section) {
    return firtp::load_machine(firtp::IniFile::parse("[FIRTP]\n" + firtp_section, "mill.ini"));
}

TEST(GcodeBlockLimit, KeyIsReadAndChecked) {
    EXPECT_EQ(firtp::default_machine().max_program_blocks, 10'000'000u);
    EXPECT_EQ(machine_with("MAX_PROGRAM_BLOCKS = 10\n").max_program_blocks, 10u);
    EXPECT_EQ(machine_with("MAX_PROGRAM_BLOCKS = 1e15\n").max_program_blocks, 1'000'000'000'000'000u);
    for (const char* bad : {"0", "-3", "2.5", "1e16"})
        EXPECT_EQ(load_error(std::string("[FIRTP]\nMAX_PROGRAM_BLOCKS = ") + bad + "\n"),
                  "mill.ini:2: [FIRTP]MAX_PROGRAM_BLOCKS: must be a whole number from 1 to 1e15");
    EXPECT_EQ(load_error("[FIRTP]\nMAX_PROGRAM_BLOCKS = many\n"),
              "mill.ini:2: [FIRTP]MAX_PROGRAM_BLOCKS: 'many' is not a number");
}

TEST(GcodeBlockLimit, LineBeyondTheLimitIsNamed) {
    const firtp::MachineConfig m = machine_with("MAX_PROGRAM_BLOCKS = 3\n");
    EXPECT_EQ(parse("G1 F600 X1\nX2\nX2\nX3\n", m).blocks.size(), 3u);  // exactly the limit (X2 twice: no block)
    EXPECT_EQ(parse_error("G1 F600 X1\nX2\nX3\n  G0 X4 M2\n", m),
              "t.ngc:4: the program needs more than 3 blocks ([FIRTP]MAX_PROGRAM_BLOCKS = 3)");
}

// A full circle of radius 5 mm at the default 0.001 mm chords: 158 chords, 164 with its end chords in pieces.
TEST(GcodeBlockLimit, ArcBeyondTheLimitIsRefusedBeforeItsChordsAreMade) {
    const std::string program = "G1 F600 X10\nX15\n G3 X15 Y0 I-5 J0\n";
    EXPECT_EQ(parse(program, machine_with("MAX_PROGRAM_BLOCKS = 166\n")).blocks.size(), 166u);
    EXPECT_EQ(parse_error(program, machine_with("MAX_PROGRAM_BLOCKS = 165\n")),
              "t.ngc:3: the program needs more than 165 blocks ([FIRTP]MAX_PROGRAM_BLOCKS = 165): this arc's 164 "
              "chords come after 2 blocks (a coarser [FIRTP]ARC_CHORD_TOLERANCE needs fewer)");
}

// A 22-byte line of 450 turns is 99,971 chords; with 10^5 blocks allowed the second such line is
// refused at once. (Without a limit, 100 lines of 4,500 turns, 2.4 kB, asked for 10^8 blocks, 11 GB.)
TEST(GcodeBlockLimit, ShortFileOfManyChordArcsIsRefused) {
    std::string program = "G1 F600 X10\n";
    for (int i = 0; i < 100; ++i) program += "G2 X10 Y0 I-10 J0 P450\n";
    const firtp::MachineConfig m = machine_with("MAX_PROGRAM_BLOCKS = 100000\n");
    EXPECT_EQ(parse_error(program, m),
              "t.ngc:3: the program needs more than 100000 blocks ([FIRTP]MAX_PROGRAM_BLOCKS = 100000): this arc's "
              "99971 chords come after 99972 blocks (a coarser [FIRTP]ARC_CHORD_TOLERANCE needs fewer)");
}

}  // namespace
