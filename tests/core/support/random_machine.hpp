// Random machines and programs for the suites of smoothing at the limits (the default mode).
//
// Machines: 2 to 5 axes, each with its own velocity (log-uniform 50-600 units/s), acceleration
// (300-30000) and jerk (1e4-1e8, one axis in ten without a jerk limit), periods of 0.25-1 ms,
// highest overrides 1, 1.2 or 2. Programs: polylines with sharp and shallow corners, reversals,
// collinear runs, zero-length blocks, long and short ones, runs of short chords along a circle
// (CAM output, arcs), some exact stops and traverses, tolerances 1 um to 1 mm. Each program is drawn
// again until segments that are not neighbours stay apart (the measurement follows the path).
#pragma once

#include "separation.hpp"
#include "soak.hpp"

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

namespace firtp::test {

struct RandomCase {
    PlannerParameters parameters;
    std::vector<Block> blocks;
};

// How far the samples' `order`-th differences over period^order can read off from rounding alone:
// positions are sums over many legs, good to about 1e-14 of their size, and the differences'
// coefficients sum to 2^order (seed 47, program 393 at a 0.25 ms period: a third difference of
// 65037.9457 on a jerk limit of 65037.8728, the samples' own jerk exactly at it; noise 0.26).
inline double difference_noise(const std::vector<AxisState>& samples, int axis, double period, int order) {
    double largest = 0.0;
    for (const AxisState& s : samples) largest = std::max(largest, std::abs(s.position[axis]));
    return std::ldexp(1e-14 * largest, order) / std::pow(period, order);
}

inline double log_uniform(std::mt19937_64& rng, double lo, double hi) {
    return lo * std::pow(hi / lo, std::uniform_real_distribution<double>(0.0, 1.0)(rng));
}

inline PlannerParameters random_machine(std::mt19937_64& rng) {
    PlannerParameters p;
    p.limits.axes = 2 + static_cast<int>(rng() % 4);
    for (int a = 0; a < p.limits.axes; ++a) {
        AxisLimits& l = p.limits.axis[a];
        l.max_velocity = log_uniform(rng, 50, 600);
        l.max_acceleration = log_uniform(rng, 300, 30000);
        l.max_jerk = rng() % 10 == 0 ? 0.0 : log_uniform(rng, 1e4, 1e8);
    }
    p.period = std::array{0.001, 0.0005, 0.00025}[rng() % 3];
    p.max_rate = std::array{1.0, 1.2, 2.0}[rng() % 3];
    p.queue_capacity = std::array<std::size_t, 3>{16, 64, 256}[rng() % 3];
    return p;
}

// A machine as firtp_cliffs --dump prints it: each axis' {velocity, acceleration, jerk}.
inline PlannerParameters drawn_machine(double period, double max_rate, const std::vector<AxisLimits>& axes) {
    PlannerParameters p;
    p.period = period;
    p.max_rate = max_rate;
    p.limits.axes = static_cast<int>(axes.size());
    for (std::size_t a = 0; a < axes.size(); ++a) p.limits.axis[static_cast<int>(a)] = axes[a];
    return p;
}

// Blocks as firtp_cliffs --dump prints them: each one's end point, feed and tolerance.
inline std::vector<Block> drawn_blocks(const std::vector<std::vector<double>>& to, const std::vector<double>& feed,
                                       const std::vector<double>& tolerance) {
    std::vector<Block> blocks(to.size());
    for (std::size_t k = 0; k < to.size(); ++k) {
        for (std::size_t a = 0; a < to[k].size(); ++a) blocks[k].target[static_cast<int>(a)] = to[k][a];
        blocks[k].feed = feed[k];
        blocks[k].tolerance = tolerance[k];
        blocks[k].line = static_cast<int>(k) + 1;
    }
    return blocks;
}

// Directions in the machine's axes (the first three mostly).
inline AxisVector random_direction(std::mt19937_64& rng, int axes) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    AxisVector d = AxisVector::Zero();
    for (int a = 0; a < axes; ++a) d[a] = unit(rng) * (a < 3 ? 1.0 : 0.3);
    if (d.norm() < 1e-3) d[0] = 1.0;
    return d.normalized();
}

inline std::vector<Block> random_blocks(std::mt19937_64& rng, const PlannerParameters& p) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int axes = p.limits.axes;
    std::vector<Block> blocks;
    AxisVector at = AxisVector::Zero(), direction = random_direction(rng, axes);
    const double tolerance = log_uniform(rng, 0.001, 1.0);
    const double feed = log_uniform(rng, 5, 600);
    const int n = 2 + static_cast<int>(rng() % 24);
    auto push = [&](const AxisVector& target, double f) {
        Block b;
        b.target = target;
        b.feed = f;
        b.tolerance = rng() % 4 == 0 ? log_uniform(rng, 0.001, 1.0) : tolerance;
        b.termination = rng() % 12 == 0 ? Termination::exact_stop : Termination::blend;
        b.type = rng() % 15 == 0 ? MotionType::traverse : MotionType::feed;
        b.line = static_cast<std::int64_t>(blocks.size()) + 1;
        blocks.push_back(b);
    };
    while (static_cast<int>(blocks.size()) < n) {
        const int kind = static_cast<int>(rng() % 10);
        const double f = rng() % 3 == 0 ? log_uniform(rng, 5, 600) : feed;
        if (kind == 0) {  // a run of chords along a circle in the X Y plane
            const double radius = log_uniform(rng, 0.5, 50), chord = log_uniform(rng, 0.02, 2.0);
            const double step = 2.0 * std::asin(std::min(1.0, chord / (2.0 * radius)));
            const int count = 3 + static_cast<int>(rng() % 30);
            const double sense = rng() % 2 ? 1.0 : -1.0;
            const double heading = std::atan2(direction[1], direction[0]);
            const double centre_angle = heading + sense * std::numbers::pi / 2;
            const AxisVector centre = at + radius * (AxisVector() << std::cos(centre_angle), std::sin(centre_angle), 0, 0, 0, 0, 0, 0, 0).finished();
            double angle = centre_angle + std::numbers::pi;
            for (int i = 0; i < count; ++i) {
                angle += sense * step;
                AxisVector next = at;
                next[0] = centre[0] + radius * std::cos(angle);
                next[1] = centre[1] + radius * std::sin(angle);
                direction = (next - at).normalized();
                at = next;
                push(at, f);
            }
            continue;
        }
        const double length = kind == 1 ? 0.0 : rng() % 3 == 0 ? log_uniform(rng, 0.01, 1.0) : log_uniform(rng, 1.0, 60.0);
        if (kind == 2) direction = -direction;                                                        // reversal
        else if (kind == 3) {}                                                                        // collinear
        else if (kind == 4) direction = (direction + 0.05 * random_direction(rng, axes)).normalized();  // shallow
        else direction = random_direction(rng, axes);
        at += direction * length;
        push(at, f);
    }
    return blocks;
}

// Programs whose path folds back onto itself are drawn again.
inline RandomCase random_case(std::mt19937_64& rng) {
    for (;;) {
        RandomCase c;
        c.parameters = random_machine(rng);
        c.blocks = random_blocks(rng, c.parameters);
        std::vector<AxisVector> points{AxisVector::Zero()};
        double tolerance = 0.0, fastest = 0.0;
        for (const Block& b : c.blocks) {
            if ((b.target - points.back()).norm() >= min_block_length) points.push_back(b.target);
            tolerance = std::max(tolerance, b.tolerance);
            fastest = std::max(fastest, b.feed * c.parameters.max_rate);
        }
        if (well_separated(points, 3 * tolerance + fastest * c.parameters.period)) return c;
    }
}

// A long program on one random machine: pieces drawn as random_blocks draws a program, each set
// to the right (+X) of those before and left along X out of its own box, so the path never comes
// back near itself. Two segments that are not neighbours stay 3 tolerances (the larger of the
// corners at their ends) and a servo step apart. A piece that does not is drawn again; a machine
// on which 300 pieces in a row do not, too.
inline RandomCase long_random_case(std::mt19937_64& rng, std::size_t blocks) {
    for (;;) {
        RandomCase c;
        c.parameters = random_machine(rng);
        std::vector<AxisVector> points{AxisVector::Zero()};
        std::vector<double> tolerance{0.0};  // of the corner at each point
        double right = 0.0, fastest = 0.0;
        for (int misses = 0; c.blocks.size() < blocks && misses < 300;) {
            std::vector<Block> piece = random_blocks(rng, c.parameters);
            double low = 0.0, high = 0.0, fast = fastest;
            for (const Block& b : piece)
                low = std::min(low, b.target[0]), high = std::max(high, b.target[0]), fast = std::max(fast, b.feed * c.parameters.max_rate);
            Block out = piece.back();
            out.target[0] = high + 2.0;
            out.termination = Termination::blend;
            piece.push_back(out);
            AxisVector shift = AxisVector::Zero();
            shift[0] = right + 5.0 - low;
            std::vector<AxisVector> p = points;
            std::vector<double> t = tolerance;
            for (Block& b : piece) {
                b.target += shift;
                b.line = static_cast<std::int64_t>(c.blocks.size()) + (&b - piece.data()) + 1;
                if ((b.target - p.back()).norm() >= min_block_length) p.push_back(b.target), t.push_back(b.tolerance);
                else t.back() = std::max(t.back(), b.tolerance);
            }
            auto gap = [&](std::size_t i, std::size_t k) {
                return 3.0 * std::max({t[i], t[i + 1], t[k], t[k + 1]}) + fast * c.parameters.period;
            };
            bool apart = true;
            for (std::size_t i = points.size() - 1; apart && i + 1 < p.size(); ++i)
                for (std::size_t k = 0; apart && k + 1 < i; ++k) apart = segment_distance(p[i], p[i + 1], p[k], p[k + 1]) >= gap(i, k);
            if (!apart) {
                ++misses;
                continue;
            }
            misses = 0;
            points = std::move(p), tolerance = std::move(t), fastest = fast;
            c.blocks.insert(c.blocks.end(), piece.begin(), piece.end());
            right = shift[0] + high + 2.0;
        }
        if (c.blocks.size() >= blocks) return c;
    }
}

// One program of firtp_cliffs (tests/bench/cliffs.cpp) as it draws it: the case, then the axis
// whose velocity, acceleration and jerk limit it raises. Tests that hold one of its programs
// (start_ramp_test.cpp) draw them the same way.
struct CliffsProgram {
    RandomCase c;
    std::array<unsigned, 3> raised_axis{};  // velocity, acceleration, jerk
};

inline CliffsProgram cliffs_program(std::mt19937_64& rng) {
    CliffsProgram p{random_case(rng), {}};
    for (unsigned& axis : p.raised_axis) axis = static_cast<unsigned>(rng() % static_cast<unsigned>(p.c.parameters.limits.axes));
    return p;
}

}  // namespace firtp::test
