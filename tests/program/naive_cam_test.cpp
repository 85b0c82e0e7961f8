// G64 Q, LinuxCNC's naive-CAM detector (component/program/src/naive_cam.hpp): the reader joins the
// straight feeds LinuxCNC's task joins. Checked against the rule written out here from the program's
// own steps (the same program read with Q0), and for what ends a collection. That the blocks are
// LinuxCNC's own is checked inside LinuxCNC: linuxcnc_tp.naive_cam_headless.
#include "gcode_test_support.hpp"
#include "../core/support/soak.hpp"

#include <firtp/gcode.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using firtp::AxisVector;
using firtp::Block;
using firtp::Program;
using firtp::test::at;
using firtp::test::parse;

constexpr std::size_t most_steps = 101;  // LinuxCNC's limit on a collection

// From p to the segment a-b, X Y Z.
double to_segment(const AxisVector& p, const AxisVector& a, const AxisVector& b) {
    const Eigen::Vector3d d = b.head<3>() - a.head<3>(), ap = p.head<3>() - a.head<3>();
    const double t = d.squaredNorm() > 0.0 ? std::clamp(ap.dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return (ap - t * d).norm();
}

// A pcb2gcode-style run: steps of 5-20 um written to 5 decimals with up to `noise` mm across,
// straight stretches, gentle curves and corners; one feed.
std::string cam_run(std::mt19937_64& rng, double noise, const std::string& g64) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::ostringstream g;
    g << "G21 G90 G17\n" << g64 << "\nF600\n";
    double x = 0.0, y = 0.0, heading = 0.0;
    char line[64];
    for (int stretch = 0; stretch < 12; ++stretch) {
        const double turn = u(rng) < 0.3 ? (u(rng) - 0.5) * 3.0 : 0.0;  // a corner now and then
        heading += turn;
        const double bend = (u(rng) - 0.5) * 0.02;  // rad a step: a curve of radius 0.5-10 mm
        const int steps = 20 + static_cast<int>(rng() % 200);
        for (int k = 0; k < steps; ++k) {
            const double step = 0.005 + 0.015 * u(rng);
            heading += bend;
            x += step * std::cos(heading) + noise * (u(rng) - 0.5) * 2.0 * -std::sin(heading);
            y += step * std::sin(heading) + noise * (u(rng) - 0.5) * 2.0 * std::cos(heading);
            std::snprintf(line, sizeof line, "G1 X%.5f Y%.5f\n", x, y);
            g << line;
        }
    }
    return g.str();
}

// Every block of `joined` ends where a step of `steps` ends (in order), the steps it joined lie
// within q of it, it joins at most 101, and it is as long as the rule makes it: the next step
// would take one of them (or its own end) farther than q from the longer segment.
void expect_linuxcnc_rule(const Program& steps, const Program& joined, double q) {
    std::vector<AxisVector> points{steps.start};
    for (const Block& b : steps.blocks) points.push_back(b.target);
    std::size_t k = 0;  // points[k]: where the block begins
    std::size_t longest = 0;
    for (std::size_t n = 0; n < joined.blocks.size(); ++n) {
        const Block& b = joined.blocks[n];
        std::size_t end = k + 1;
        while (end < points.size() && points[end] != b.target) ++end;
        ASSERT_LT(end, points.size()) << "block " << n << " does not end on a step";
        ASSERT_EQ(b.line, steps.blocks[end - 1].line) << "block " << n << " carries its last step's line";
        const std::size_t count = end - k;
        longest = std::max(longest, count);
        ASSERT_LE(count, most_steps) << "block " << n;
        for (std::size_t m = k + 1; m < end; ++m)
            ASSERT_LE(to_segment(points[m], points[k], b.target), q) << "block " << n << " step " << m;
        if (end + 1 < points.size() && count < most_steps) {
            double farthest = 0.0;
            for (std::size_t m = k + 1; m <= end; ++m) farthest = std::max(farthest, to_segment(points[m], points[k], points[end + 1]));
            ASSERT_GT(farthest, q) << "block " << n << " could have taken the next step";
        }
        k = end;
    }
    ASSERT_EQ(k + 1, points.size()) << "the blocks end where the steps end";
    EXPECT_EQ(joined.joined.moves, steps.blocks.size() - joined.blocks.size());
    EXPECT_GT(longest, 1u);
}

// FIRTP_RANDOM_SEED and FIRTP_RANDOM_SCALE as in the other randomized suites.
TEST(NaiveCam, JoinsTheStepsTheRuleJoins) {
    std::mt19937_64 rng(11 + firtp::test::random_seed_offset());
    const int count = firtp::test::random_scaled(40);
    std::size_t steps = 0, blocks = 0;
    for (int n = 0; n < count; ++n) {
        const double noise = n % 2 == 0 ? 0.0 : 0.002 * (1 + n % 5);
        const double q = n % 3 == 0 ? 0.005 : 0.01;
        std::mt19937_64 a = rng, b = rng;
        const Program every = parse(cam_run(a, noise, "G64 P0.01 Q0"));
        const Program joined = parse(cam_run(b, noise, n % 3 == 0 ? "G64 P0.01 Q0.005" : "G64 P0.01"));
        rng = a;
        SCOPED_TRACE("program " + std::to_string(n));
        expect_linuxcnc_rule(every, joined, q);
        EXPECT_EQ(every.joined.moves, 0u);
        steps += every.blocks.size(), blocks += joined.blocks.size();
    }
    std::printf("%zu steps joined into %zu blocks\n", steps, blocks);
}

// Steps from..to of 8 um x 6 um along one line.
std::string collinear(int from, int to) {
    std::string g;
    char line[64];
    for (int i = from; i <= to; ++i) std::snprintf(line, sizeof line, "G1 X%.3f Y%.3f\n", 0.008 * i, 0.006 * i), g += line;
    return g;
}

TEST(NaiveCam, AtMost101StepsABlock) {
    const Program p = parse("G64 P0.01\nF600\n" + collinear(1, 250));
    ASSERT_EQ(p.blocks.size(), 3u);
    EXPECT_EQ(p.blocks[0].line, 3 + 100);
    EXPECT_EQ(p.blocks[1].line, 3 + 201);
    EXPECT_EQ(p.blocks[2].line, 3 + 249);
    EXPECT_EQ(p.joined.moves, 247u);
    EXPECT_LT(p.joined.farthest, 1e-12);
}

TEST(NaiveCam, QZeroG64AloneAndExactStopsKeepEveryStep) {
    for (const char* mode : {"G64 P0.01 Q0", "G64", "G64 P0", "G61", "G61.1"}) {
        const Program p = parse(std::string(mode) + "\nF600\n" + collinear(1, 50));
        EXPECT_EQ(p.blocks.size(), 50u) << mode;
        EXPECT_EQ(p.joined.moves, 0u) << mode;
    }
    // A step 0.015 mm off the line from X1 to X3: within Q 0.02, not within 0.01.
    const std::string bump = "F600\nG1 X1 Y0\nG1 X2 Y0.015\nG1 X3 Y0\n";
    EXPECT_EQ(parse("G64 P0.01\n" + bump).blocks.size(), 2u);  // X1 joins, X3 cannot
    EXPECT_EQ(parse("G64 P0.01 Q0.02\n" + bump).blocks.size(), 1u);
    EXPECT_EQ(parse("G64 P0.02\n" + bump).blocks.size(), 1u);  // Q = P
}

// LinuxCNC ends a collection at each of these; the events keep their place between the blocks.
TEST(NaiveCam, AnythingElseEndsACollection) {
    for (const char* between : {"F300", "M8", "M3 S1000", "G4 P0.5", "G0 X0.096 Y0.072", "G92 X0", "G61"}) {
        const Program p = parse("G64 P0.01\nF600\n" + collinear(1, 10) + between + "\n" + collinear(13, 20));
        SCOPED_TRACE(between);
        ASSERT_GE(p.blocks.size(), 2u);
        EXPECT_EQ(p.blocks[0].line, 3 + 9);  // the first ten steps: one block
        for (const firtp::ProgramEvent& e : p.events) {
            if (e.line == 13) {
                EXPECT_EQ(e.before_block, 1u) << event_name(e.kind);
            }
        }
    }
    const Program same_feed = parse("G64 P0.01\nF600\n" + collinear(1, 10) + "F600\n" + collinear(11, 20));
    ASSERT_EQ(same_feed.blocks.size(), 1u);  // F as it was: the run goes on
}

TEST(NaiveCam, RotaryMotionMovesAlone) {
    const Program p = parse("G64 P0.01\nF600\nG1 X1\nG1 X2\nG1 X3 A1\nG1 X4 A1\nG1 X5 A1\n", firtp::test::nine_axis_machine());
    ASSERT_EQ(p.blocks.size(), 3u);
    EXPECT_EQ(p.blocks[0].target, at({{'X', 2}}));
    EXPECT_EQ(p.blocks[1].target, at({{'X', 3}, {'A', 1}}));
    EXPECT_EQ(p.blocks[2].target, at({{'X', 5}, {'A', 1}}));
}

// An XY arc whose chord deviation is below Q joins as two steps through its middle (at the middle
// angle, on the start's radius); one of G18, a second turn or a larger deviation is chorded.
TEST(NaiveCam, ShortXYArcsJoinThroughTheirMiddle) {
    // A quarter of R 0.02 from (1, 0) about (1, 0.02): deviation 0.02 (1 - cos 45 deg) = 0.0059.
    // X1 and the middle lie within 0.0059 of the line from the start to the middle, X1 does not of
    // the line to the arc's end; the arc's end then joins the step after it.
    const Program p = parse("G64 P0.01\nF600\nG1 X1\nG3 X1.02 Y0.02 J0.02\nG1 X1.02 Y1\n");
    const double h = std::sqrt(0.5) * 0.02;
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_LT((p.blocks[0].target - at({{'X', 1.0 + h}, {'Y', 0.02 - h}})).norm(), 1e-12) << "the arc's middle";
    EXPECT_EQ(p.blocks[0].line, 4);
    EXPECT_EQ(p.blocks[1].target, at({{'X', 1.02}, {'Y', 1}}));
    EXPECT_EQ(p.joined.moves, 2u);
    // Chorded as with Q0: deviation 0.059 (R 0.2), the XZ plane, two turns.
    for (const char* arc : {"G3 X1.2 Y0.2 J0.2", "G18 G2 X1.02 Z0.02 K0.02", "G3 X1.02 Y0.02 J0.02 P2"}) {
        const std::string rest = std::string("F600\nG1 X1\n") + arc + "\n";
        EXPECT_EQ(parse("G64 P0.01\n" + rest).blocks.size(), parse("G64 P0.01 Q0\n" + rest).blocks.size()) << arc;
        EXPECT_GT(parse("G64 P0.01\n" + rest).blocks.size(), 2u) << arc;
    }
}

}  // namespace
