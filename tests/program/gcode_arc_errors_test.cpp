// G2 / G3 errors: each names file:line:column.
#include "gcode_test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using firtp::test::parse_error;

TEST(GcodeArcErrors, CentreWords) {
    EXPECT_EQ(parse_error("G2 F600 X1 Y1"),
              "t.ngc:1:1: G2 in the XY plane (G17) needs its centre: I and J words, or R");
    EXPECT_EQ(parse_error("G18\nF600\nG3 X1"),
              "t.ngc:3:1: G3 in the XZ plane (G18) needs its centre: K and I words, or R");
    EXPECT_EQ(parse_error("G19 G2 F1 Y1\n"),
              "t.ngc:1:5: G2 in the YZ plane (G19) needs its centre: J and K words, or R");
    EXPECT_EQ(parse_error("G2 F600 X1\nY1 I1"),
              "t.ngc:1:1: G2 in the XY plane (G17) needs its centre: I and J words, or R");
    EXPECT_EQ(parse_error("G17 G2 F600 X1 K1"),
              "t.ngc:1:16: K word given for an arc in the XY plane (G17): use I and J");
    EXPECT_EQ(parse_error("G18 G2 F600 X1 J1 I1"),
              "t.ngc:1:16: J word given for an arc in the XZ plane (G18): use K and I");
    EXPECT_EQ(parse_error("G19 G2 F600 Y1 I1"),
              "t.ngc:1:16: I word given for an arc in the YZ plane (G19): use J and K");
    EXPECT_EQ(parse_error("G2 F600 X1 I1 R1"), "t.ngc:1:15: an arc takes either R or I J K words, not both");
    EXPECT_EQ(parse_error("G2 F600 X1 R1 J1"), "t.ngc:1:15: an arc takes either R or I J K words, not both");
    EXPECT_EQ(parse_error("G90.1 G2 F600 X2 I1"),
              "t.ngc:1:7: J word missing for an arc with an absolute centre (G90.1)");
    EXPECT_EQ(parse_error("G90.1\nG18 G2 F600 X2 I1 K0\nG3 X0 I1"),
              "t.ngc:3:1: K word missing for an arc with an absolute centre (G90.1)");
}

TEST(GcodeArcErrors, Radii) {
    EXPECT_EQ(parse_error("G0 X10\nG3 F600 X0 Y10.1 I-10"),
              "t.ngc:2:1: radius to end of arc differs from radius to start (start 10.0000 mm, end 10.1000 mm)");
    // LinuxCNC's tolerances: 0.0283 mm (G21) or 0.00283 in (G20), and 0.1 % of the radius.
    EXPECT_EQ(parse_error("G0 X100\nG3 F600 X0 Y100.02 I-100"), "no error");
    EXPECT_EQ(parse_error("G0 X100\nG3 F600 X0 Y100.03 I-100"),
              "t.ngc:2:1: radius to end of arc differs from radius to start (start 100.0000 mm, end 100.0300 mm)");
    EXPECT_EQ(parse_error("G0 X10\nG3 F600 X0 Y10.009 I-10"), "no error");
    EXPECT_EQ(parse_error("G0 X10\nG3 F600 X0 Y10.011 I-10"),
              "t.ngc:2:1: radius to end of arc differs from radius to start (start 10.0000 mm, end 10.0110 mm)");
    EXPECT_EQ(parse_error("G20 G0 X10\nG3 F60 X0 Y10.0028 I-10"), "no error");
    EXPECT_EQ(parse_error("G20 G0 X10\nG3 F60 X0 Y10.0029 I-10"),
              "t.ngc:2:1: radius to end of arc differs from radius to start (start 254.0000 mm, end 254.0737 mm)");
    EXPECT_EQ(parse_error("G3 F600 X1 Y0 I0 J0"),
              "t.ngc:1:1: zero-radius arc: the centre is on the start or the end point "
              "(start 0.0000 mm, end 1.0000 mm)");
    EXPECT_EQ(parse_error("G3 F600 X2 I1.0004"), "no error");  // radii 1.0004 and 0.9996: a spiral within 0.1 %
    EXPECT_EQ(parse_error("G2 F600 X0.001 I0.0005"),
              "t.ngc:1:1: zero-radius arc: the centre is on the start or the end point "
              "(start 0.0005 mm, end 0.0005 mm)");
}

TEST(GcodeArcErrors, RadiusForm) {
    EXPECT_EQ(parse_error("G2 F600 X10 R4"),
              "t.ngc:1:13: radius 4.0000 mm is too small to reach the end point (half the chord is 5.0000 mm)");
    EXPECT_EQ(parse_error("G2 F600 X10 R-4.99"),
              "t.ngc:1:13: radius 4.9900 mm is too small to reach the end point (half the chord is 5.0000 mm)");
    EXPECT_EQ(parse_error("G2 F600 X10 R4.999"), "no error");
    EXPECT_EQ(parse_error("G0 X5\nG2 F600 X5 Y0 Z1 R5"),
              "t.ngc:2:18: an R arc cannot be a full circle: the end point equals the start point (use I J K)");
    EXPECT_EQ(parse_error("G2 F600 Z1 R5"),
              "t.ngc:1:12: an R arc cannot be a full circle: the end point equals the start point (use I J K)");
}

TEST(GcodeArcErrors, FeedTurnsAndWords) {
    EXPECT_EQ(parse_error("G2 X1 I1"), "t.ngc:1:1: cannot do G2 with zero feed rate: program an F word first");
    EXPECT_EQ(parse_error("G1 F0\nX1 I1 G3"), "t.ngc:2:7: cannot do G3 with zero feed rate: program an F word first");
    EXPECT_EQ(parse_error("G2 F600 X0 I1 P0"),
              "t.ngc:1:15: G2 P is the number of turns: a whole number from 1 to 10000");
    EXPECT_EQ(parse_error("G3 F600 X0 I1 P1.5"),
              "t.ngc:1:15: G3 P is the number of turns: a whole number from 1 to 10000");
    EXPECT_EQ(parse_error("G3 F600 X0 I1 P2"), "no error");
    EXPECT_EQ(parse_error("G2 F600 I1 J1"), "t.ngc:1:9: word 'I' with no axis word: an arc needs its end point");
    EXPECT_EQ(parse_error("G2 F600 X2 I1\nG0 X0 J1"), "t.ngc:2:7: word 'J' with no G2 or G3 to use it");
}

TEST(GcodeArcErrors, TooManyChords) {
    firtp::MachineConfig m = firtp::default_machine();
    m.arc_chord_tolerance = 1e-12;
    EXPECT_EQ(parse_error("G0 X1000\nG3 F600 X1000 I-1000", m),
              "t.ngc:2:1: the arc needs more than 1000000 chords: raise [FIRTP]ARC_CHORD_TOLERANCE");
    m.arc_chord_tolerance = 1e-9;
    EXPECT_EQ(parse_error("G0 X10\nG3 F600 X0 Y10 I-10", m), "no error");  // 55,536 chords
}

}  // namespace
