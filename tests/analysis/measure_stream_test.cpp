// The streamed measurement against the batch one it replaced (batch_measure_reference.cpp): equal
// bit for bit on planned trajectories and on random sampled paths made to stress the tracking
// (micrometre segments, reversals, repeated points, samples jumping many segments, NaN).
#include "batch_measure_reference.hpp"
#include "trajectories.hpp"

#include <firtp/machine.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace firtp {
namespace {

using test::sample_period;
using test::axes;

void expect_same(const Measured& a, const Measured& b, const std::string& what) {
    SCOPED_TRACE(what);
    ASSERT_EQ(a.corner_errors.size(), b.corner_errors.size());
    for (std::size_t i = 0; i < a.corner_errors.size(); ++i)
        ASSERT_EQ(a.corner_errors[i], b.corner_errors[i]) << "corner " << i;
    EXPECT_EQ(a.cycle_time, b.cycle_time);
    EXPECT_EQ(a.max_corner_error, b.max_corner_error);
    EXPECT_EQ(a.max_contour_error, b.max_contour_error);
    EXPECT_EQ(a.max_path_speed, b.max_path_speed);
    EXPECT_EQ(a.max_velocity, b.max_velocity);
    EXPECT_EQ(a.max_acceleration, b.max_acceleration);
    EXPECT_EQ(a.max_jerk, b.max_jerk);
    EXPECT_EQ(a.end_position, b.end_position);
    EXPECT_EQ(a.finite, b.finite);
}

// A random polyline: short and long segments, micrometre runs, reversals, repeated points.
std::vector<AxisVector> random_points(std::mt19937& rng, std::size_t count) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), u01(0.0, 1.0);
    std::vector<AxisVector> points{axes(0, 0, 0)};
    AxisVector direction = axes(1, 0, 0);
    while (points.size() < count) {
        const double pick = u01(rng);
        const double length = pick < 0.4 ? 0.001 + 0.01 * u01(rng) : pick < 0.8 ? 0.5 * u01(rng) : 5.0 * u01(rng);
        if (pick < 0.05) direction = -direction;  // reversal
        else if (pick < 0.1) { points.push_back(points.back()); continue; }  // zero-length block
        else direction = (direction + 0.8 * axes(unit(rng), unit(rng), 0.2 * unit(rng))).normalized();
        points.push_back(points.back() + length * direction);
    }
    return points;
}

// Samples along the polyline at a random varying speed (sometimes many segments per sample),
// pushed off the path by up to `stray`, now and then a NaN.
std::vector<AxisState> random_samples(std::mt19937& rng, const std::vector<AxisVector>& points, double stray,
                                      bool with_nan) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), u01(0.0, 1.0);
    std::vector<AxisVector> path;
    double step = 0.05;
    std::size_t k = 0;
    double along = 0.0;
    while (k + 1 < points.size()) {
        const AxisVector delta = points[k + 1] - points[k];
        const double length = delta.norm();
        if (along >= length) { along -= length; ++k; continue; }
        AxisVector p = points[k] + (length > 0.0 ? along / length : 0.0) * delta;
        p += stray * axes(unit(rng), unit(rng), unit(rng));
        if (with_nan && u01(rng) < 0.002) p[1] = std::numeric_limits<double>::quiet_NaN();
        path.push_back(p);
        if (u01(rng) < 0.05) step = std::exp(std::log(0.0005) + u01(rng) * std::log(4.0 / 0.0005));
        along += step;
    }
    path.push_back(points.back());
    return test::timed(path, sample_period);
}

TEST(MeasureStream, EqualsTheBatchMeasurementOnRandomPaths) {
    std::mt19937 rng(14);
    for (int run = 0; run < 1000; ++run) {
        const std::size_t count = 2 + static_cast<std::size_t>(run % 60);
        const std::vector<AxisVector> points = random_points(rng, count);
        const double stray = (run % 3) * 0.02;
        const std::vector<AxisState> samples = random_samples(rng, points, stray, run % 7 == 0);
        expect_same(measure(samples, points, sample_period), reference::measure_batch(samples, points, sample_period),
                    "run " + std::to_string(run));
        if (HasFatalFailure()) return;
    }
}

TEST(MeasureStream, EqualsTheBatchMeasurementOnFewSamplesAndPoints) {
    std::mt19937 rng(15);
    for (std::size_t n = 0; n < 6; ++n)
        for (std::size_t count = 0; count < 5; ++count) {
            std::vector<AxisVector> points = count ? random_points(rng, count) : std::vector<AxisVector>{};
            std::vector<AxisVector> positions;
            for (std::size_t i = 0; i < n; ++i) positions.push_back(axes(0.3 * static_cast<double>(i), 0.1));
            const auto samples = test::timed(positions, sample_period);
            expect_same(measure(samples, points, sample_period), reference::measure_batch(samples, points, sample_period),
                        "n " + std::to_string(n) + " points " + std::to_string(count));
        }
}

TEST(MeasureStream, EqualsTheBatchMeasurementOnPlannedDensePaths) {
    // A planned zig-zag of micrometre to 0.3 mm blocks: the planner cuts across within tolerance.
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const PlannerParameters parameters = default_machine().planner_parameters();  // 1 ms
    std::vector<Block> blocks;
    std::vector<AxisVector> points{AxisVector::Zero()};
    for (int i = 0; i < 2000; ++i) {
        Block b;
        b.target = points.back() + axes(0.002 + 0.3 * u01(rng), (i % 2 ? 1.0 : -1.0) * 0.2 * u01(rng));
        b.feed = 100.0;
        b.tolerance = 0.02;
        b.line = i + 1;
        blocks.push_back(b);
        points.push_back(b.target);
    }
    const Trajectory t = plan_trajectory(parameters, AxisVector::Zero(), blocks);
    expect_same(measure(t.samples, points, sample_period), reference::measure_batch(t.samples, points, sample_period), "planned");
}

TEST(MeasureStream, ToldEachCornerOnceInOrder) {
    std::mt19937 rng(17);
    const std::vector<AxisVector> points = random_points(rng, 200);
    const std::vector<AxisState> samples = random_samples(rng, points, 0.01, false);
    std::vector<double> told;
    MeasureStream stream(points, sample_period, [&](std::size_t i, double e) {
        EXPECT_EQ(i, told.size());
        told.push_back(e);
    });
    for (const AxisState& s : samples) stream.add(s);
    const Measured m = stream.finish();
    EXPECT_EQ(told, m.corner_errors);
    EXPECT_GT(told.size(), 100u);
}

}  // namespace
}  // namespace firtp
