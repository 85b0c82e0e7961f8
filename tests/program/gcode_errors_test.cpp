#include <firtp/gcode.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

using firtp::GcodeError;

std::string error(std::string_view text, const firtp::MachineConfig& machine = firtp::default_machine()) {
    try {
        firtp::parse_gcode(text, "t.ngc", machine);
    } catch (const GcodeError& e) {
        return e.what();
    }
    return "no error";
}

TEST(GcodeErrors, CarryFileLineAndColumn) {
    try {
        firtp::parse_gcode("G1 F60 X1\n\n  G1 X2 Y1.2.3\n", "part.ngc", firtp::default_machine());
        FAIL() << "no error";
    } catch (const GcodeError& e) {
        EXPECT_EQ(e.file(), "part.ngc");
        EXPECT_EQ(e.line(), 3);
        EXPECT_EQ(e.column(), 9);
        EXPECT_STREQ(e.what(), "part.ngc:3:9: malformed number in 'Y1.2.3': write digits with at most one "
                               "decimal point and no exponent");
    }
}

TEST(GcodeErrors, MissingFile) {
    try {
        firtp::read_gcode("/nonexistent/part.ngc", firtp::default_machine());
        FAIL() << "no error";
    } catch (const GcodeError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/part.ngc:0:0: cannot open file");
        EXPECT_EQ(e.line(), 0);
        EXPECT_EQ(e.column(), 0);
    }
    EXPECT_THROW(firtp::read_gcode(FIRTP_PROGRAM_DATA, firtp::default_machine()), GcodeError);  // a directory
}

TEST(GcodeErrors, UnsupportedLetters) {
    EXPECT_EQ(error("E2 G1 F60 X1"), "t.ngc:1:1: word 'E' is not supported");
    EXPECT_EQ(error("G1 F60 X1\nh1 G43"), "t.ngc:2:1: word 'H' is not supported");
    EXPECT_EQ(error("G1 F60 X1 D2"), "t.ngc:1:11: word 'D' is not supported");
    EXPECT_EQ(error("L2 G10 P1"), "t.ngc:1:1: word 'L' is not supported");
    EXPECT_EQ(error("T1 M6"), "t.ngc:1:1: word 'T' is not supported");
    EXPECT_EQ(error("S1000"), "t.ngc:1:1: word 'S' is not supported");
    EXPECT_EQ(error("O100 sub"), "t.ngc:1:1: word 'O' is not supported");
}

TEST(GcodeErrors, AxisWordsBeyondTheMachine) {
    EXPECT_EQ(error("G1 F60 A1"), "t.ngc:1:8: axis word 'A' but the machine has 3 axes");
    EXPECT_EQ(error("G1 F60 X1 w2"), "t.ngc:1:11: axis word 'W' but the machine has 3 axes");
    firtp::MachineConfig four = firtp::default_machine();
    four.limits.axes = 4;
    EXPECT_EQ(error("G1 F60 A1 X1", four), "no error");
    EXPECT_EQ(error("G1 F60 A1\nG0 B2", four), "t.ngc:2:4: axis word 'B' but the machine has 4 axes");
    four.limits.axes = 9;
    EXPECT_EQ(error("G1 F60 A1 B1 C1 U1 V1 W1", four), "no error");
}

TEST(GcodeErrors, UnsupportedCodes) {
    EXPECT_EQ(error("G5 X1 Y1"), "t.ngc:1:1: G5 is not supported");
    EXPECT_EQ(error("G1 F60 X1\n G05.1 X1"), "t.ngc:2:2: G5.1 is not supported");
    EXPECT_EQ(error("G38.2 Z-1"), "t.ngc:1:1: G38.2 is not supported");
    EXPECT_EQ(error("G1.5 X1"), "t.ngc:1:1: G1.5 is not supported");
    EXPECT_EQ(error("G1.25 X1"), "t.ngc:1:1: G1.25 is not supported");
    EXPECT_EQ(error("G-1 X1"), "t.ngc:1:1: G-1 is not supported");
    EXPECT_EQ(error("M3 S1"), "t.ngc:1:1: M3 is not supported");
    EXPECT_EQ(error("G1 F60 X1 M0"), "t.ngc:1:11: M0 is not supported");
    EXPECT_EQ(error("G93 G1 F1 X1"), "t.ngc:1:1: G93 is not supported");
    EXPECT_EQ(error("G95"), "t.ngc:1:1: G95 is not supported");
    EXPECT_EQ(error("G33 Z-1 K1"), "t.ngc:1:1: G33 is not supported");
    EXPECT_EQ(error("G81 Z-1 R1"), "t.ngc:1:1: G81 is not supported");
    EXPECT_EQ(error("G17.1"), "t.ngc:1:1: G17.1 is not supported");
}

TEST(GcodeErrors, PlanesArcModesFeedModeAndQAreAccepted) {
    EXPECT_EQ(error("G18\nG19\nG17\nG90.1\nG91.1\nG94\nG64 P0.1 Q0.05\nG64 Q0\n"), "no error");
    EXPECT_EQ(error("G18 G19"), "t.ngc:1:5: G18 and G19 are in the same modal group: use one per line");
    EXPECT_EQ(error("G90.1 G91.1"), "t.ngc:1:7: G90.1 and G91.1 are in the same modal group: use one per line");
    EXPECT_EQ(error("G90 G91.1 G94 G94"), "t.ngc:1:15: G94 appears twice on this line");
}

TEST(GcodeErrors, SameModalGroupTwice) {
    EXPECT_EQ(error("G0 G1 X1"), "t.ngc:1:4: G0 and G1 are in the same modal group: use one per line");
    EXPECT_EQ(error("G20 G21"), "t.ngc:1:5: G20 and G21 are in the same modal group: use one per line");
    EXPECT_EQ(error("G90 G91"), "t.ngc:1:5: G90 and G91 are in the same modal group: use one per line");
    EXPECT_EQ(error("G61 G64"), "t.ngc:1:5: G61 and G64 are in the same modal group: use one per line");
    EXPECT_EQ(error("G61.1 G61"), "t.ngc:1:7: G61.1 and G61 are in the same modal group: use one per line");
    EXPECT_EQ(error("G1 G01 F60 X1"), "t.ngc:1:4: G1 appears twice on this line");
    EXPECT_EQ(error("M2 M30"), "t.ngc:1:4: M2 and M30 are in the same modal group: use one per line");
}

TEST(GcodeErrors, RepeatedWords) {
    EXPECT_EQ(error("G1 F60 X1 X2"), "t.ngc:1:11: more than one X word on this line");
    EXPECT_EQ(error("G1 F60 F70 X1"), "t.ngc:1:8: more than one F word on this line");
    EXPECT_EQ(error("N1 N2"), "t.ngc:1:4: more than one N word on this line");
}

TEST(GcodeErrors, MalformedNumbers) {
    const std::string tail = "': write digits with at most one decimal point and no exponent";
    EXPECT_EQ(error("G1 F60 X"), "t.ngc:1:8: word 'X' has no number");
    EXPECT_EQ(error("G1 F60 X Y1"), "t.ngc:1:8: word 'X' has no number");
    EXPECT_EQ(error("G F60"), "t.ngc:1:1: word 'G' has no number");
    EXPECT_EQ(error("G1 F60 X1.2.3"), "t.ngc:1:8: malformed number in 'X1.2.3" + tail);
    EXPECT_EQ(error("G1 F60 X-"), "t.ngc:1:8: malformed number in 'X-" + tail);
    EXPECT_EQ(error("G1 F60 X- Y1"), "t.ngc:1:8: malformed number in 'X-" + tail);
    EXPECT_EQ(error("G1 F60 X1e3"), "t.ngc:1:8: malformed number in 'X1e3" + tail);
    EXPECT_EQ(error("G1 F60 X."), "t.ngc:1:8: malformed number in 'X." + tail);
    EXPECT_EQ(error("G1 F60 X+-1"), "t.ngc:1:8: malformed number in 'X+-1" + tail);
    EXPECT_EQ(error("G1 F60 X[1+2]"), "t.ngc:1:8: word 'X' has no number");
    EXPECT_EQ(error("G1 F60 X1-2"), "t.ngc:1:8: malformed number in 'X1-2" + tail);
    EXPECT_EQ(error("G1 F60 X1 Y2.E-3"), "t.ngc:1:11: malformed number in 'Y2.E-3" + tail);
}

TEST(GcodeErrors, BadCharactersAndComments) {
    EXPECT_EQ(error("G1 F60 X1 @"), "t.ngc:1:11: unexpected character '@'");
    EXPECT_EQ(error("#1 = 5"), "t.ngc:1:1: unexpected character '#'");
    EXPECT_EQ(error("/G1 X1"), "t.ngc:1:1: unexpected character '/'");
    EXPECT_EQ(error("G1 F60 X1 )"), "t.ngc:1:11: unexpected character ')'");
    EXPECT_EQ(error("G1 % X1"), "t.ngc:1:4: '%' must be alone on its line");
    EXPECT_EQ(error("%\nG1 F60 X1\n%x\n"), "t.ngc:3:1: '%' must be alone on its line");
    EXPECT_EQ(error("G1 F60\n\tX1 (move"), "t.ngc:2:5: comment is not closed: missing ')'");
    EXPECT_EQ(error("G1 (a (b) ) X1"), "t.ngc:1:7: '(' inside a comment: comments do not nest");
}

TEST(GcodeErrors, WordsWithNothingToUseThem) {
    EXPECT_EQ(error("G1 F60 X1 P0.1"), "t.ngc:1:11: word 'P' with no G64, G2 or G3 to use it");
    EXPECT_EQ(error("G61 P1"), "t.ngc:1:5: word 'P' with no G64, G2 or G3 to use it");
    EXPECT_EQ(error("G64 P-0.1"), "t.ngc:1:5: G64 P must not be negative");
    EXPECT_EQ(error("G64 P0.1 Q-1"), "t.ngc:1:10: G64 Q must not be negative");
    EXPECT_EQ(error("G61 Q1"), "t.ngc:1:5: word 'Q' with no G64 to use it");
    EXPECT_EQ(error("G1 F60 X1 Q1"), "t.ngc:1:11: word 'Q' with no G64 to use it");
    EXPECT_EQ(error("G1 F60 X1 I1"), "t.ngc:1:11: word 'I' with no G2 or G3 to use it");
    EXPECT_EQ(error("G1 F60 X1\nG1 X2 R1 J1"), "t.ngc:2:7: word 'R' with no G2 or G3 to use it");
    EXPECT_EQ(error("K1"), "t.ngc:1:1: word 'K' with no G2 or G3 to use it");
    EXPECT_EQ(error("G2 F60 I1"), "t.ngc:1:8: word 'I' with no axis word: an arc needs its end point");
    EXPECT_EQ(error("G2 F60 X1 I1 G64 P1"),
              "t.ngc:1:18: word 'P' is used by both G64 and G2: put them on separate lines");
}

TEST(GcodeErrors, MotionAndFeed) {
    EXPECT_EQ(error("X1"), "t.ngc:1:1: X word with no motion in effect: program G0 or G1 first");
    EXPECT_EQ(error("F60 G90 Y1 X2"), "t.ngc:1:9: Y word with no motion in effect: program G0 or G1 first");
    EXPECT_EQ(error("G1 X1"), "t.ngc:1:1: cannot do G1 with zero feed rate: program an F word first");
    EXPECT_EQ(error("G0 X1\nG1\nY2 X1"), "t.ngc:3:1: cannot do G1 with zero feed rate: program an F word first");
    EXPECT_EQ(error("F0\nX1 G1"), "t.ngc:2:4: cannot do G1 with zero feed rate: program an F word first");
    EXPECT_EQ(error("G1 F-100 X1"), "t.ngc:1:4: negative feed rate 'F-100'");

    firtp::MachineConfig no_limits = firtp::default_machine();
    no_limits.limits.axis[0].max_velocity = 0.0;
    EXPECT_EQ(error("G0 Y1\nG0 X1", no_limits),
              "t.ngc:2:1: G0 needs the axes' MAX_VELOCITY: this machine has no rapid speed");
    EXPECT_EQ(error("G1 F60 X1\nG0 X2 Y1", no_limits), "no error");  // Y limits the diagonal
}

TEST(GcodeErrors, WordsAfterProgramEndOnItsLineAreChecked) {
    EXPECT_EQ(error("M2 A1"), "t.ngc:1:4: axis word 'A' but the machine has 3 axes");
    EXPECT_EQ(error("M2 D1"), "t.ngc:1:4: word 'D' is not supported");
    EXPECT_EQ(error("M30\nA1"), "no error");
}

}  // namespace
