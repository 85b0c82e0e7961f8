// G2 / G3 arcs as chord blocks: geometry, direction per plane, helices, turns and feeds.
#include "gcode_test_support.hpp"

#include <firtp/arc_chords.hpp>
#include <firtp/text_cat.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace {

using firtp::AxisVector;
using firtp::Block;
using firtp::MachineConfig;
using firtp::Program;
using firtp::Termination;
using firtp::test::at;
using firtp::test::durations;
using firtp::test::parse;
using firtp::test::points;
using firtp::test::total;

constexpr double pi = std::numbers::pi;

Eigen::Index axis(char letter) {
    return static_cast<Eigen::Index>(std::string_view("XYZABCUVW").find(letter));
}

// The chord rule: sagitta R (1 - cos(d / 2)) <= tol, at least 4 a turn, at least 1.
// The chords of equal angle the tolerance needs, their end chords then cut into pieces
// (arc_chords.hpp, tested in tests/core/arc_chords_test.cpp).
int expected_chords(double sweep, double radius, double tol) {
    const double by_sagitta = std::ceil(sweep / (4.0 * std::asin(std::sqrt(tol / (2.0 * radius)))));
    const double by_turn = std::ceil(sweep / (pi / 2) - 1e-9);
    return firtp::graded_chord_count(static_cast<int>(std::max({1.0, by_sagitta, by_turn})));
}

// Every chord end on the circle and every chord's sagitta within the tolerance.
void expect_on_circle(const Program& p, char first, char second, double cu, double cv, double radius, double tol) {
    const std::vector<AxisVector> pts = points(p);
    for (std::size_t k = 0; k < pts.size(); ++k) {
        const Eigen::Vector2d q(pts[k][axis(first)] - cu, pts[k][axis(second)] - cv);
        EXPECT_NEAR(q.norm(), radius, 1e-9) << "chord end " << k;
        if (k == 0) continue;
        const AxisVector mid = (pts[k] + pts[k - 1]) / 2.0;
        const double sagitta = radius - std::hypot(mid[axis(first)] - cu, mid[axis(second)] - cv);
        EXPECT_LE(sagitta, tol + 1e-12) << "chord " << k;
        EXPECT_GE(sagitta, 0.0);
    }
}

// The angle the chord ends turn through about (cu, cv), counter-clockwise positive.
double turned(const Program& p, char first, char second, double cu = 0.0, double cv = 0.0) {
    double sum = 0.0;
    const std::vector<AxisVector> pts = points(p);
    for (std::size_t k = 1; k < pts.size(); ++k) {
        const double from = std::atan2(pts[k - 1][axis(second)] - cv, pts[k - 1][axis(first)] - cu);
        const double to = std::atan2(pts[k][axis(second)] - cv, pts[k][axis(first)] - cu);
        sum += std::remainder(to - from, 2.0 * pi);
    }
    return sum;
}

struct PlaneCase {
    const char* g;      // G17, G18, G19
    char first;         // the arc turns counter-clockwise from first towards second
    char second;
    char first_centre;  // centre word of `first`
    char normal;
};

class QuarterArc : public testing::TestWithParam<std::pair<PlaneCase, bool>> {};

// From first = 10 a quarter turn about the origin: G3 to second = 10, G2 to second = -10.
TEST_P(QuarterArc, TurnsTheProgrammedWay) {
    const auto& [plane, clockwise] = GetParam();
    const std::string text = firtp::cat(plane.g, clockwise ? " G2" : " G3", " F600 ", plane.first, "0 ", plane.second,
                                        clockwise ? "-10 " : "10 ", plane.first_centre, "-10\n");
    const Program p = parse(text, firtp::default_machine(), at({{plane.first, 10.0}}));
    const int n = expected_chords(pi / 2, 10.0, 0.001);
    ASSERT_EQ(static_cast<int>(p.blocks.size()), n) << text;
    ASSERT_EQ(n % 2, 0);
    expect_on_circle(p, plane.first, plane.second, 0.0, 0.0, 10.0, 0.001);

    const double side = clockwise ? -1.0 : 1.0;
    const AxisVector mid = p.blocks[static_cast<std::size_t>(n / 2 - 1)].target;
    EXPECT_NEAR(mid[axis(plane.first)], 10.0 / std::sqrt(2.0), 1e-9) << text;
    EXPECT_NEAR(mid[axis(plane.second)], side * 10.0 / std::sqrt(2.0), 1e-9) << text;
    EXPECT_EQ(mid[axis(plane.normal)], 0.0);
    double previous = 0.0;
    for (const Block& b : p.blocks) {
        const double angle = std::atan2(b.target[axis(plane.second)], b.target[axis(plane.first)]);
        EXPECT_GT(side * (angle - previous), 0.0) << (clockwise ? "clockwise" : "counter-clockwise");
        previous = angle;
    }
    EXPECT_EQ(p.blocks.back().target, at({{plane.second, side * 10.0}}));  // the programmed end, bit for bit
}

INSTANTIATE_TEST_SUITE_P(EveryPlane, QuarterArc,
                         testing::Values(std::pair{PlaneCase{"G17", 'X', 'Y', 'I', 'Z'}, false},
                                         std::pair{PlaneCase{"G17", 'X', 'Y', 'I', 'Z'}, true},
                                         std::pair{PlaneCase{"G18", 'Z', 'X', 'K', 'Y'}, false},
                                         std::pair{PlaneCase{"G18", 'Z', 'X', 'K', 'Y'}, true},
                                         std::pair{PlaneCase{"G19", 'Y', 'Z', 'J', 'X'}, false},
                                         std::pair{PlaneCase{"G19", 'Y', 'Z', 'J', 'X'}, true}));

TEST(GcodeArc, G18CounterClockwiseSeenFromPlusY) {
    // Seen from +Y (Z to the right, X up), G3 from +Z goes up towards +X.
    const Program p = parse("G18 G3 F600 X10 Z0 K-10\n", firtp::default_machine(), at({{'Z', 10.0}}));
    const AxisVector second = p.blocks[1].target;
    EXPECT_GT(second[axis('X')], 0.0);
    EXPECT_LT(second[axis('Z')], 10.0);
}

TEST(GcodeArc, ChordsAreOnTheCircleWithinTheSagittaTolerance) {
    MachineConfig m = firtp::default_machine();
    for (const double tol : {0.001, 0.01, 0.2}) {
        m.arc_chord_tolerance = tol;
        // From (0, 0) clockwise about (3, 4), radius 5, to (6, 0): the long way, over the top.
        const Program p = parse("G2 F600 X6 Y0 I3 J4\n", m);
        const double sweep = 2.0 * pi - 2.0 * std::atan2(3.0, 4.0);
        EXPECT_EQ(static_cast<int>(p.blocks.size()), expected_chords(sweep, 5.0, tol)) << tol;
        expect_on_circle(p, 'X', 'Y', 3.0, 4.0, 5.0, tol);
        EXPECT_EQ(p.blocks.back().target, at({{'X', 6.0}}));
    }
    m.arc_chord_tolerance = 100.0;  // sagitta no constraint: four chords a turn, one for a quarter
    EXPECT_EQ(parse("G3 F600 X-1 Y0 I-1 J0\n", m, at({{'X', 1.0}})).blocks.size(), 2u + 6u);  // 2 chords, ends in pieces
    EXPECT_EQ(parse("G3 F600 X1 Y0 I-1 J0\n", m, at({{'X', 1.0}})).blocks.size(), 4u + 6u);
    EXPECT_EQ(parse("G3 F600 X0 Y1 I-1 J0\n", m, at({{'X', 1.0}})).blocks.size(), 1u);
    EXPECT_EQ(parse("G3 F600 X0.70711 Y0.70711 I-1 J0\n", m, at({{'X', 1.0}})).blocks.size(), 1u);
}

TEST(GcodeArc, ChordToleranceComesFromTheIni) {
    const MachineConfig m =
        firtp::load_machine(firtp::IniFile::parse("[FIRTP]\nARC_CHORD_TOLERANCE = 0.05\n", "m.ini"));
    const Program p = parse("G3 F600 X0 Y10 I-10\n", m, at({{'X', 10.0}}));
    EXPECT_EQ(static_cast<int>(p.blocks.size()), expected_chords(pi / 2, 10.0, 0.05));  // 8 + 6 instead of 56 + 6
    expect_on_circle(p, 'X', 'Y', 0.0, 0.0, 10.0, 0.05);
}

TEST(GcodeArc, EndIsExactlyTheProgrammedPoint) {
    // The end is 5 mm from the centre only to about 1e-5: a slight spiral, within LinuxCNC's tolerance.
    const Program p = parse("G0 X6 Y2 Z1\nG3 F600 X-1.0807 Y6.5465 Z2.25 I-5 J0\n");
    const AxisVector end = at({{'X', -1.0807}, {'Y', 6.5465}, {'Z', 2.25}});
    ASSERT_GT(p.blocks.size(), 2u);
    EXPECT_EQ(p.blocks.back().target, end);
    for (const Block& b : p.blocks) EXPECT_NEAR(std::hypot(b.target[0] - 1.0, b.target[1] - 2.0), 5.0, 2e-5);
}

TEST(GcodeArc, RadiusAndCentreFormsGiveTheSameChords) {
    const auto same = [](const Program& a, const Program& b) {
        ASSERT_EQ(a.blocks.size(), b.blocks.size());
        for (std::size_t k = 0; k < a.blocks.size(); ++k) {
            EXPECT_LT((a.blocks[k].target - b.blocks[k].target).norm(), 1e-9) << k;
            EXPECT_NEAR(a.blocks[k].feed, b.blocks[k].feed, 1e-9) << k;
        }
    };
    const Program r_short = parse("G2 F600 X10 Y10 R10\n");  // centre (10, 0), a quarter turn
    same(r_short, parse("G2 F600 X10 Y10 I10 J0\n"));
    EXPECT_EQ(static_cast<int>(r_short.blocks.size()), expected_chords(pi / 2, 10.0, 0.001));

    const Program r_long = parse("G2 F600 X10 Y10 R-10\n");  // centre (0, 10), three quarters
    same(r_long, parse("G2 F600 X10 Y10 I0 J10\n"));
    EXPECT_EQ(static_cast<int>(r_long.blocks.size()), expected_chords(1.5 * pi, 10.0, 0.001));
    expect_on_circle(r_long, 'X', 'Y', 0.0, 10.0, 10.0, 0.001);
    EXPECT_LT(r_long.blocks[r_long.blocks.size() / 3].target[0], -9.0);  // round by the left, not the short way

    same(parse("G3 F600 X10 Y10 R-10\n"), parse("G3 F600 X10 Y10 I10 J0\n"));
    same(parse("G19 G3 F600 Y10 Z10 R10\n"), parse("G19 G3 F600 Y10 Z10 K10\n"));
    same(parse("G2 F600 X10 R4.999\n"), parse("G2 F600 X10 I5\n"));  // within 0.00127 mm: a half circle
}

TEST(GcodeArc, FullCircleAndTurns) {
    const AxisVector start = at({{'X', 10.0}});
    const Program one = parse("G3 F600 X10 Y0 I-10\n", firtp::default_machine(), start);
    const int n = expected_chords(2.0 * pi, 10.0, 0.001);
    ASSERT_EQ(static_cast<int>(one.blocks.size()), n);
    expect_on_circle(one, 'X', 'Y', 0.0, 0.0, 10.0, 0.001);
    EXPECT_EQ(one.blocks.back().target, start);
    EXPECT_GT(one.blocks[static_cast<std::size_t>(n / 4)].target[1], 9.0);  // counter-clockwise: up first

    EXPECT_NEAR(turned(one, 'X', 'Y'), 2.0 * pi, 1e-9);

    const Program two = parse("G3 F600 X10 I-10 P2\n", firtp::default_machine(), start);
    EXPECT_EQ(static_cast<int>(two.blocks.size()), expected_chords(4.0 * pi, 10.0, 0.001));
    expect_on_circle(two, 'X', 'Y', 0.0, 0.0, 10.0, 0.001);
    EXPECT_NEAR(turned(two, 'X', 'Y'), 4.0 * pi, 1e-9);
    EXPECT_EQ(two.blocks.back().target, start);

    const Program part = parse("G2 F600 X0 Y10 I-10 P3\n", firtp::default_machine(), start);  // 2 turns + 3/4
    EXPECT_EQ(static_cast<int>(part.blocks.size()), expected_chords(5.5 * pi, 10.0, 0.001));
    EXPECT_EQ(part.blocks.back().target, at({{'Y', 10.0}}));
    EXPECT_NEAR(turned(part, 'X', 'Y'), -5.5 * pi, 1e-9);
}

TEST(GcodeArc, HelixMovesTheOtherAxesLinearlyWithTheAngle) {
    MachineConfig m = firtp::test::nine_axis_machine();
    const Program p = parse("G3 F600 X0 Y10 Z5 A90 U-2 I-10 P2\n", m, at({{'X', 10.0}}));
    const double sweep = 2.5 * pi;
    double turned = 0.0, previous = 0.0;
    for (const Block& b : p.blocks) {
        const double angle = std::atan2(b.target[1], b.target[0]);
        turned += std::remainder(angle - previous, 2.0 * pi);
        previous = angle;
        EXPECT_NEAR(b.target[axis('Z')], 5.0 * turned / sweep, 1e-9);
        EXPECT_NEAR(b.target[axis('A')], 90.0 * turned / sweep, 1e-9);
        EXPECT_NEAR(b.target[axis('U')], -2.0 * turned / sweep, 1e-9);
        EXPECT_NEAR(std::hypot(b.target[0], b.target[1]), 10.0, 1e-9);
    }
    EXPECT_NEAR(turned, sweep, 1e-9);

    const Program g18 = parse("G18 G2 F600 Z0 X20 Y-3 I10\n", m);  // centre (Z 0, X 10), Y is the helix axis
    ASSERT_GT(g18.blocks.size(), 2u);
    const AxisVector mid = g18.blocks[g18.blocks.size() / 2 - 1].target;
    EXPECT_NEAR(mid[axis('Y')], -1.5, 1e-9);
}

TEST(GcodeArc, AbsoluteCentresWithG90_1) {
    const auto same = [](const Program& a, const Program& b) {
        ASSERT_EQ(a.blocks.size(), b.blocks.size());
        for (std::size_t k = 0; k < a.blocks.size(); ++k)
            EXPECT_LT((a.blocks[k].target - b.blocks[k].target).norm(), 1e-12) << k;
    };
    const AxisVector start = at({{'X', 12.0}, {'Y', 3.0}});
    const Program incremental = parse("G3 F600 X2 Y13 I-10 J0\n", firtp::default_machine(), start);
    same(incremental, parse("G90.1 G3 F600 X2 Y13 I2 J3\n", firtp::default_machine(), start));
    // G91 makes the end incremental; the centre stays absolute under G90.1.
    same(incremental, parse("G91 G90.1 G3 F600 X-10 Y10 I2 J3\n", firtp::default_machine(), start));
    same(incremental, parse("G90.1\nG91.1 G3 F600 X2 Y13 I-10\n", firtp::default_machine(), start));
    same(parse("G18 G90.1 G2 F600 Z10 X0 K5 I0\n"), parse("G18 G2 F600 Z10 X0 K5\n"));
}

TEST(GcodeArc, InchesScaleEndsCentresAndRadius) {
    const Program p = parse("G20 G3 F60 X0 Y1 I-1\n", firtp::default_machine(), at({{'X', 25.4}}));
    expect_on_circle(p, 'X', 'Y', 0.0, 0.0, 25.4, 0.001);
    EXPECT_EQ(p.blocks.back().target, at({{'Y', 25.4}}));
    const Program r = parse("G20 G3 F60 X0 Y1 R1\n", firtp::default_machine(), at({{'X', 25.4}}));
    expect_on_circle(r, 'X', 'Y', 0.0, 0.0, 25.4, 0.001);
}

TEST(GcodeArc, DurationsSumToArcLengthOverFeed) {
    const Program flat = parse("G3 F600 X0 Y10 I-10\n", firtp::default_machine(), at({{'X', 10.0}}));
    EXPECT_NEAR(total(durations(flat)), (pi / 2 * 10.0) / 10.0, 1e-12);
    const std::vector<double> each = durations(flat);
    const std::vector<AxisVector> pts = points(flat);
    for (std::size_t k = 0; k < each.size(); ++k) {  // one speed along the arc, whatever the chord's length
        const double arc = 10.0 * (std::atan2(pts[k + 1][1], pts[k + 1][0]) - std::atan2(pts[k][1], pts[k][0]));
        EXPECT_NEAR(each[k], arc / 10.0, 1e-12) << k;
    }

    const Program helix = parse("G3 F600 X0 Y10 Z4 I-10 P2\n", firtp::default_machine(), at({{'X', 10.0}}));
    EXPECT_NEAR(total(durations(helix)), std::hypot(2.5 * pi * 10.0, 4.0) / 10.0, 1e-12);

    // A B C U V W ride along: F still applies to the X Y Z helix.
    const Program with_a = parse("G3 F600 X0 Y10 A90 W5 I-10\n", firtp::test::nine_axis_machine(), at({{'X', 10.0}}));
    EXPECT_NEAR(total(durations(with_a)), (pi / 2 * 10.0) / 10.0, 1e-12);
}

TEST(GcodeArc, FeedIsCappedWhereTheFiltersWouldShrinkTheCircle) {
    MachineConfig m = firtp::default_machine();
    m.given_times = {0.1, 0.05};  // sum T^2 = 0.0125 s^2
    const double length = pi / 2 * 20.0;
    const AxisVector start = at({{'X', 20.0}});
    const auto time = [&](const std::string& text) { return total(durations(parse(text, m, start))); };

    // Shrink F^2 sum(T^2) / (24 R) within 90 % of the tolerance (the rest for chords and junctions).
    const auto cap = [](double radius, double tolerance, double squares) {
        return std::sqrt(24.0 * radius * 0.9 * tolerance / squares);
    };
    const double v_cap = cap(20.0, 0.02, 0.0125);  // 26.3 mm/s
    EXPECT_NEAR(time("G64 P0.02\nG3 F6000 X0 Y20 I-20\n"), length / v_cap, 1e-12);
    EXPECT_NEAR(time("G64 P0.02\nG3 F600 X0 Y20 I-20\n"), length / 10.0, 1e-12);  // slower than the cap
    EXPECT_NEAR(time("G64 P0\nG3 F6000 X0 Y20 I-20\n"), length / cap(20.0, 0.05, 0.0125), 1e-12);  // as G64
    EXPECT_NEAR(time("G64 G3 F6000 X0 Y20 I-20\n"), length / cap(20.0, 0.05, 0.0125), 1e-12);
    EXPECT_NEAR(time("G61 G3 F6000 X0 Y20 I-20\n"), length / cap(20.0, 0.05, 0.0125), 1e-12);
    EXPECT_NEAR(time("G64 P0.02\nG1 F6000 X0 Y20\n"), std::hypot(20.0, 20.0) / 100.0, 1e-12);  // lines: no cap

    m.stages = 3;
    m.given_times = {0.1, 0.05, 0.02};
    EXPECT_NEAR(time("G64 P0.02\nG3 F6000 X0 Y20 I-20\n"), length / cap(20.0, 0.02, 0.0129), 1e-12);

    MachineConfig unknown = firtp::default_machine();  // no filter times: no cap
    unknown.limits.axis[0] = unknown.limits.axis[1] = unknown.limits.axis[2] = firtp::AxisLimits{};
    EXPECT_THROW(unknown.filter_times(), firtp::ConfigError);
    EXPECT_NEAR(total(durations(parse("G64 P0.02\nG3 F6000 X0 Y20 I-20\n", unknown, start))), length / 100.0, 1e-12);
}

TEST(GcodeArc, AxisVelocityLimitsCapTheArcSpeed) {
    MachineConfig m = firtp::default_machine();
    m.limits.axis[0].max_velocity = 5.0;
    const Program p = parse("G64 P0\nG3 F6000 X0 Y10 I-10\n", m, at({{'X', 10.0}}));
    double fastest_x = 0.0;
    AxisVector from = p.start;
    for (const Block& b : p.blocks) {
        const double duration = (b.target - from).norm() / b.feed;
        fastest_x = std::max(fastest_x, std::abs(b.target[0] - from[0]) / duration);
        from = b.target;
    }
    EXPECT_NEAR(fastest_x, 5.0, 1e-9);  // the chord nearest Y10 moves X the fastest

    m.limits.max_linear_velocity = 2.0;
    EXPECT_NEAR(total(durations(parse("G64 P0\nG3 F6000 X0 Y10 I-10\n", m, at({{'X', 10.0}})))), pi / 2 * 10.0 / 2.0,
                1e-12);

    MachineConfig slow_a = firtp::test::nine_axis_machine();
    slow_a.limits.axis[3].max_velocity = 9.0;  // deg/s: 90 degrees take at least 10 s
    EXPECT_NEAR(total(durations(parse("G64 P0\nG3 F6000 X0 Y10 A90 I-10\n", slow_a, at({{'X', 10.0}})))), 10.0, 1e-9);
}

TEST(GcodeArc, ChordsBlendInsideAndEndAsTheArcDoes) {
    MachineConfig m = firtp::default_machine();
    m.default_tolerance = 0.03;
    const Program stop = parse("G61\nG3 F600 X0 Y10 I-10\n", m, at({{'X', 10.0}}));
    ASSERT_GT(stop.blocks.size(), 2u);
    for (std::size_t k = 0; k + 1 < stop.blocks.size(); ++k) {
        EXPECT_EQ(stop.blocks[k].termination, Termination::blend);
        EXPECT_EQ(stop.blocks[k].tolerance, 0.03);
    }
    EXPECT_EQ(stop.blocks.back().termination, Termination::exact_stop);
    EXPECT_EQ(stop.blocks.back().tolerance, 0.0);

    const Program blend = parse("G64 P0.2\nN7 G2 F600 X0 Y-10 I-10\nG1 X5\n", m, at({{'X', 10.0}}));
    for (std::size_t k = 0; k + 1 < blend.blocks.size(); ++k) {
        EXPECT_EQ(blend.blocks[k].termination, Termination::blend);
        EXPECT_DOUBLE_EQ(blend.blocks[k].tolerance, 0.2);
        EXPECT_EQ(blend.blocks[k].type, firtp::MotionType::feed);
        EXPECT_EQ(blend.blocks[k].line, 2);
    }
    EXPECT_EQ(blend.blocks.back().line, 3);
}

TEST(GcodeArc, ArcModeIsModal) {
    const Program p = parse("G3 F600 X0 Y10 I-10\nX-10 Y0 J-10\nG1 X0\n", firtp::default_machine(), at({{'X', 10.0}}));
    const int quarter = expected_chords(pi / 2, 10.0, 0.001);
    ASSERT_EQ(static_cast<int>(p.blocks.size()), 2 * quarter + 1);
    EXPECT_EQ(p.blocks[static_cast<std::size_t>(2 * quarter - 1)].target, at({{'X', -10.0}}));
    EXPECT_EQ(p.blocks[static_cast<std::size_t>(2 * quarter - 1)].line, 2);
}

}  // namespace
