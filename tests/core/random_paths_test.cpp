// Seeded randomized suite: random 2-D and 3-D polylines with sharp and shallow corners, reversals,
// collinear runs, zero-length, long and short blocks, 1-4 stages, fractional periods and times.
// Invariants, measured on the sampled output: corner error <= epsilon at every blended corner,
// end point exact, speed <= F, no NaN.
#include "support/reference.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <random>

using namespace firtp;

namespace {

struct RandomProgram {
    PlannerParameters parameters;
    std::vector<Block> blocks;
    double max_feed = 0.0;
};

RandomProgram random_program(std::mt19937_64& rng, bool three_d) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
    RandomProgram p;
    FilterTimes& f = p.parameters.filters;
    f.stages = 1 + static_cast<int>(rng() % 4);
    for (int i = 0; i < f.stages; ++i) f.T[i] = log_uniform(0.002, 0.15);
    std::sort(f.T.begin(), f.T.begin() + f.stages, std::greater<>());
    p.parameters.period = std::array{0.001, 0.0005, 0.00025, 0.0008}[rng() % 4];

    const int n = 2 + static_cast<int>(rng() % 10);
    const bool constant_feed = rng() % 2 == 0;
    const double feed0 = log_uniform(5, 400);
    const double tolerance = log_uniform(0.001, 1.0);
    AxisVector at = AxisVector::Zero(), direction = test::xyz(1, 0, 0);
    for (int i = 0; i < n; ++i) {
        Block b;
        b.line = i + 1;
        b.feed = constant_feed ? feed0 : log_uniform(5, 400);
        b.tolerance = rng() % 3 == 0 ? log_uniform(0.001, 1.0) : tolerance;
        b.termination = rng() % 10 == 0 ? Termination::exact_stop : Termination::blend;
        b.type = MotionType::feed;
        const int kind = static_cast<int>(rng() % 10);
        const double length = kind == 0 ? 0.0 : rng() % 3 == 0 ? log_uniform(0.01, 1) : log_uniform(1, 60);
        if (kind == 1) direction = -direction;                   // reversal
        else if (kind == 2) {}                                   // collinear continuation
        else if (kind == 3) {                                    // shallow corner
            direction = (direction + 0.05 * test::xyz(unit(rng) - 0.5, unit(rng) - 0.5, three_d ? unit(rng) - 0.5 : 0)).normalized();
        } else {
            direction = test::xyz(unit(rng) - 0.5, unit(rng) - 0.5, three_d ? unit(rng) - 0.5 : 0).normalized();
        }
        at += direction * length;
        b.target = at;
        p.max_feed = std::max(p.max_feed, b.feed);
        p.blocks.push_back(b);
    }
    return p;
}

void check_paths(std::uint64_t seed, int count, bool three_d, ToleranceMeaning meaning) {
    std::mt19937_64 rng(seed);
    for (int k = 0; k < count; ++k) {
        RandomProgram p = random_program(rng, three_d);
        p.parameters.tolerance_meaning = meaning;
        const Trajectory t = plan_trajectory(p.parameters, AxisVector::Zero(), p.blocks);
        std::vector<AxisVector> points{AxisVector::Zero()};
        std::vector<const Block*> ending;  // block ending at each programmed point
        for (const Block& b : p.blocks)
            if ((b.target - points.back()).norm() >= 1e-9) points.push_back(b.target), ending.push_back(&b);
        const Measured m = measure(t.samples, points, p.parameters.period);
        SCOPED_TRACE("seed " + std::to_string(seed) + " program " + std::to_string(k));

        ASSERT_TRUE(m.finite);
        ASSERT_EQ(m.end_position, p.blocks.back().target);  // exact, bit for bit
        ASSERT_EQ(t.samples.back().velocity, AxisVector::Zero());
        ASSERT_LE(m.max_path_speed, p.max_feed * (1 + 1e-9));
        ASSERT_EQ(m.corner_errors.size(), points.size() - 2);
        for (std::size_t c = 0; c < m.corner_errors.size(); ++c) {
            const Block& b = *ending[c];
            if (meaning == ToleranceMeaning::corner_point && b.termination == Termination::blend) {
                ASSERT_LE(m.corner_errors[c], b.tolerance) << "corner " << c << " line " << b.line;
            }
        }
    }
}

}  // namespace

TEST(RandomPaths, PlanarCornerPointTolerance) { check_paths(1, 1500, false, ToleranceMeaning::corner_point); }
TEST(RandomPaths, SpatialCornerPointTolerance) { check_paths(2, 1500, true, ToleranceMeaning::corner_point); }

TEST(RandomPaths, ContourToleranceHoldsOnTheWholePath) {
    std::mt19937_64 rng(3);
    for (int k = 0; k < 800; ++k) {
        RandomProgram p = random_program(rng, k % 2 == 0);
        p.parameters.tolerance_meaning = ToleranceMeaning::contour;
        double smallest = 1e300;
        for (Block& b : p.blocks) smallest = std::min(smallest, b.tolerance);
        for (Block& b : p.blocks) b.tolerance = smallest;
        const Trajectory t = plan_trajectory(p.parameters, AxisVector::Zero(), p.blocks);
        std::vector<AxisVector> points{AxisVector::Zero()};
        for (const Block& b : p.blocks) points.push_back(b.target);
        const Measured m = measure(t.samples, points, p.parameters.period);
        ASSERT_LE(m.max_contour_error, smallest * (1 + 1e-6) + 1e-9) << "program " << k;
        ASSERT_EQ(m.end_position, p.blocks.back().target);
    }
}
