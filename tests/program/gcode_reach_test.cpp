// Coordinates far beyond any machine are refused where they are written. fuzz_gcode found that
// G1 Y444...4 (165 digits: 4.4e164, finite) read without an error and gave a block whose feed was
// NaN: the move's length squared overflowed to inf. The reader now refuses an end point or a chord
// beyond +-1e6 machine units (the limit messages::validate applies to every block on LCM).
#include <firtp/gcode.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

std::string error(std::string_view text) {
    try {
        const firtp::Program p = firtp::parse_gcode(std::string(text) + "\nM2\n", "t.ngc", firtp::default_machine());
        for (const firtp::Block& b : p.blocks)
            if (!(std::isfinite(b.feed) && b.feed > 0.0)) return "a block with feed " + std::to_string(b.feed);
    } catch (const firtp::GcodeError& e) {
        return e.what();
    }
    return "no error";
}

TEST(GcodeReach, EndPointsBeyondAMillionAreRefusedAtTheirWord) {
    EXPECT_EQ(error("G1 F600 X10 Y" + std::string(165, '4') + "\n"),
              "t.ngc:1: the move passes beyond +-1e6 machine units");
    EXPECT_EQ(error("G21 G1 F600 X1000001\n"), "t.ngc:1: the move passes beyond +-1e6 machine units");
    EXPECT_EQ(error("G20 G1 F60 Z40000\n"), "t.ngc:1: the move passes beyond +-1e6 machine units");
    EXPECT_EQ(error("G91 G1 F600 X600000\nX600000\n"), "t.ngc:2: the move passes beyond +-1e6 machine units");
    EXPECT_EQ(error("G1 F600 X1000000 Y-1000000\n"), "no error");
}

TEST(GcodeReach, ArcsPassingBeyondAMillionAreRefused) {
    // A full circle of radius 1e7 around a centre far away: its end point is its start.
    EXPECT_EQ(error("G1 F600 X1\nG2 X1 Y0 I10000000 J0\n"), "t.ngc:2: the move passes beyond +-1e6 machine units");
}

}  // namespace
