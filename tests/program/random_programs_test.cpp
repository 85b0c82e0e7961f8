// Seeded randomized suite over G-code: lines, G2/G3 arcs in G17/G18/G19 with I J K or R, helices,
// and moves with rotary axes (A, B in degrees), on a five-axis machine with limits. Each program
// goes through the reader and the planner; measured on the sampled output: every blended junction
// (chord junctions inside arcs included) within its tolerance, v, a, j within the axis limits in
// the finite differences, the end exactly on the last point, no NaN. FIRTP_RANDOM_SEED and
// FIRTP_RANDOM_SCALE as in the core suite.
#include "gcode_test_support.hpp"
#include "../core/support/soak.hpp"

#include <firtp/machine.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

namespace {

using firtp::AxisVector;
using firtp::Block;

firtp::MachineConfig five_axis() {
    firtp::MachineConfig m = firtp::default_machine();
    m.limits.axes = 5;
    m.limits.axis[2] = {200.0, 4000.0, 100000.0};
    m.limits.axis[3] = m.limits.axis[4] = {90.0, 1500.0, 30000.0};
    return m;
}

// A program that moves on in +X with every element, so that no part of it comes back near an
// earlier one (the measurement follows the path from junction to junction).
std::string random_program(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::ostringstream g;
    g.precision(6);
    g << std::fixed << "G21 G90 G64 P" << 0.005 + 0.1 * unit(rng) << "\nF" << 600 + 9000 * unit(rng) << "\n";
    double x = 0, y = 0, z = 0, a = 0, b = 0;
    Eigen::Vector3d heading(1, 0, 0);  // direction of travel at the end of the last element
    // Junctions turn by less than 120 degrees: at a reversal between two arcs the path comes back
    // along itself and no measurement can tell which samples belong to which junction.
    auto turns_less = [&](const Eigen::Vector3d& next) { return heading.dot(next.normalized()) > -0.5; };
    const int elements = 3 + static_cast<int>(rng() % 6);
    for (int e = 0; e < elements; ++e) {
        if (rng() % 4 == 0) g << "G64 P" << 0.005 + 0.1 * unit(rng) << "\n";
        if (rng() % 5 == 0) g << "F" << 600 + 9000 * unit(rng) << "\n";
        const int kind = static_cast<int>(rng() % 4);
        if (kind == 0) {  // line, sometimes with rotary motion
            Eigen::Vector3d d(2 + 20 * unit(rng), 10 * (unit(rng) - 0.5), 4 * (unit(rng) - 0.5));
            for (int tries = 0; tries < 100 && !turns_less(d); ++tries) d.y() = -d.y(), d.z() = -d.z(), d.x() *= 3;
            if (!turns_less(d)) continue;
            x += d.x();
            y += d.y();
            z += d.z();
            heading = d.normalized();
            g << "G1 X" << x << " Y" << y << " Z" << z;
            if (rng() % 2 == 0) g << " A" << (a += 60 * (unit(rng) - 0.5));
            if (rng() % 3 == 0) g << " B" << (b += 30 * (unit(rng) - 0.5));
            g << "\n";
        } else {  // a quarter arc (or less) in a plane that contains X, ending further along +X
            const bool xz = kind == 2;
            const double r = 2 + 15 * unit(rng), sweep = std::numbers::pi / 2 * (0.3 + 0.7 * unit(rng));
            // Angles from +X towards Y (G17) or towards Z (G18); redrawn until the arc ends further along +X.
            const double v = xz ? z : y;
            bool increasing = false;
            double cx = 0, cv = 0, ex = x, ev = v;
            Eigen::Vector3d start_tangent = Eigen::Vector3d::Zero(), end_tangent = Eigen::Vector3d::Zero();
            auto tangent = [&](double angle, double sense) {  // in 3-D, along the motion
                const double tx = -std::sin(angle) * sense, tv = std::cos(angle) * sense;
                return xz ? Eigen::Vector3d(tx, 0, tv) : Eigen::Vector3d(tx, tv, 0);
            };
            for (int tries = 0; tries < 200 && (ex < x + 0.2 * r || tries == 0 || !turns_less(start_tangent)); ++tries) {
                const double start = 2 * std::numbers::pi * unit(rng);
                increasing = rng() % 2 == 0;
                cx = x - r * std::cos(start);
                cv = v - r * std::sin(start);
                const double end = start + (increasing ? sweep : -sweep);
                ex = cx + r * std::cos(end);
                ev = cv + r * std::sin(end);
                start_tangent = tangent(start, increasing ? 1 : -1);
                end_tangent = tangent(end, increasing ? 1 : -1);
            }
            if (ex < x + 0.2 * r || !turns_less(start_tangent)) continue;
            heading = end_tangent;
            // G17: counter-clockwise (G3) seen from +Z is an increasing angle. G18 is seen from +Y with
            // the angle running from Z to X: an increasing X-to-Z angle is clockwise (G2) there.
            const bool g2 = xz ? increasing : !increasing;
            const bool helix = !xz && rng() % 3 == 0;
            const bool radius_form = rng() % 3 == 0;
            g << (xz ? "G18 " : "G17 ") << (g2 ? "G2" : "G3") << " X" << ex << (xz ? " Z" : " Y") << ev;
            if (helix) g << " Z" << (z += 3 * (unit(rng) - 0.5));
            if (radius_form) g << " R" << r;
            else if (xz) g << " I" << cx - x << " K" << cv - z;
            else g << " I" << cx - x << " J" << cv - y;
            g << "\n";
            x = ex;
            (xz ? z : y) = ev;
            if (rng() % 3 == 0 && turns_less(Eigen::Vector3d(0, 1, 0.6))) {  // a short arc in YZ, 60 degrees
                g << "G19 G2 Y" << (y += 3) << " Z" << z << " R3\n";
                heading = Eigen::Vector3d(0, 1, -0.6).normalized();
            }
        }
    }
    g << "G17\nM2\n";
    return g.str();
}

}  // namespace

TEST(RandomPrograms, ArcsHelicesAndRotaryAxesKeepToleranceLimitsAndEnd) {
    std::mt19937_64 rng(5 + firtp::test::random_seed_offset());  // soak runs: core/support/soak.hpp
    const int count = firtp::test::random_scaled(150);
    const firtp::MachineConfig machine = five_axis();
    const firtp::PlannerParameters parameters = machine.planner_parameters();
    int arcs = 0, junctions = 0;
    double worst_error = 0.0, worst_limit = 0.0;
    for (int k = 0; k < count; ++k) {
        const std::string text = random_program(rng);
        SCOPED_TRACE("program " + std::to_string(k) + ":\n" + text);
        const firtp::Program program = firtp::test::parse(text, machine);
        const firtp::Trajectory t = firtp::plan_trajectory(parameters, program.start, program.blocks);
        const std::vector<AxisVector> points = firtp::test::points(program);
        const firtp::Measured m = firtp::measure(t.samples, points, parameters.period);
        ASSERT_TRUE(m.finite);
        ASSERT_EQ(m.end_position, program.blocks.back().target);
        for (int a = 0; a < 5; ++a) {
            const firtp::AxisLimits& l = machine.limits.axis[a];
            ASSERT_LE(m.max_velocity[a], l.max_velocity * (1 + 1e-6)) << "axis " << a;
            ASSERT_LE(m.max_acceleration[a], l.max_acceleration * (1 + 1e-6)) << "axis " << a;
            ASSERT_LE(m.max_jerk[a], l.max_jerk * (1 + 1e-6)) << "axis " << a;
            worst_limit = std::max({worst_limit, m.max_acceleration[a] / l.max_acceleration, m.max_jerk[a] / l.max_jerk});
        }
        ASSERT_EQ(m.corner_errors.size(), points.size() - 2);
        for (std::size_t c = 0; c < m.corner_errors.size(); ++c) {
            const Block& b = program.blocks[c];
            if (b.termination != firtp::Termination::blend) continue;
            ++junctions;
            ASSERT_LE(m.corner_errors[c], b.tolerance * (1 + 1e-9)) << "junction after line " << b.line;
            worst_error = std::max(worst_error, m.corner_errors[c] / b.tolerance);
        }
        arcs += static_cast<int>(std::count(text.begin(), text.end(), 'R') + std::count(text.begin(), text.end(), 'I'));
    }
    std::printf("%d programs, %d arcs, %d junctions: worst error / tolerance %.4f, worst a or j / limit %.4f\n", count,
                arcs, junctions, worst_error, worst_limit);
}
