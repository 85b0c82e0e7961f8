// Degenerate inputs, exact path following, and a long program.
#include "trajectories.hpp"

#include <firtp/measure.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace firtp {
namespace {

using test::sample_period;
using test::append_line;
using test::axes;
using test::timed;

// Samples exactly on the polyline, every programmed point included.
std::vector<AxisVector> on_polyline(const std::vector<AxisVector>& points, int steps) {
    std::vector<AxisVector> out;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) append_line(out, points[k], points[k + 1], steps);
    out.push_back(points.back());
    return out;
}

TEST(MeasureEdge, FollowingThePolylineGivesNoError) {
    const std::vector<AxisVector> points{axes(0, 0, 0), axes(3, 1, 0), axes(3, 4, 2), axes(-1, 4, 2), axes(0, 0, 0)};
    const Measured m = measure(timed(on_polyline(points, 37), sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 3u);
    for (double e : m.corner_errors) EXPECT_LT(e, 1e-12);
    EXPECT_LT(m.max_contour_error, 1e-12);
    EXPECT_TRUE(m.end_position.isApprox(points.back()));
}

TEST(MeasureEdge, OffsetFromPolylineIsTheContourError) {
    // A straight path 0.25 to the side of a straight program.
    const std::vector<AxisVector> points{axes(0, 0), axes(10, 0)};
    const Measured m = measure(timed(on_polyline({axes(0, 0.25), axes(10, 0.25)}, 100), sample_period), points, sample_period);
    EXPECT_TRUE(m.corner_errors.empty());
    EXPECT_NEAR(m.max_contour_error, 0.25, 1e-12);
    EXPECT_EQ(m.max_corner_error, 0.0);
}

// The measurement works over the axes that have moved so far; an axis that first moves late (W,
// the ninth) still counts, in the path's points and in the samples alike.
TEST(MeasureEdge, AnAxisThatMovesLateCounts) {
    AxisVector corner = axes(10), end = axes(10);
    end(8) = 4.0;
    const std::vector<AxisVector> points{axes(0), corner, end};
    // Along X to 9, straight across the corner to W = 1, then on along W; 0.3 off in V on the way.
    AxisVector cut = axes(10), last = end;
    cut(8) = 1.0;
    last(7) = 0.3;
    std::vector<AxisVector> path;
    append_line(path, axes(0), axes(9), 90);
    append_line(path, axes(9), cut, 10);
    append_line(path, cut, last, 30);
    path.push_back(last);
    const Measured m = measure(timed(path, sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_NEAR(m.corner_errors[0], std::sqrt(0.5), 1e-12);  // the corner from the chord (9, w 0) -> (10, w 1)
    EXPECT_NEAR(m.max_contour_error, 0.5, 1e-12);  // the chord's middle, (9.5, w 0.5)
    const Measured off = measure(timed({axes(0), axes(5), corner, last}, sample_period), points, sample_period);
    EXPECT_NEAR(off.max_contour_error, 0.3, 1e-12);  // V alone is off the path, at the end
}

TEST(MeasureEdge, NonFiniteSamples) {
    const std::vector<AxisVector> points{axes(0), axes(1)};
    auto samples = timed(on_polyline(points, 10), sample_period);
    EXPECT_TRUE(measure(samples, points, sample_period).finite);
    samples[4].position(7) = std::numeric_limits<double>::quiet_NaN();
    const Measured with_nan = measure(samples, points, sample_period);
    EXPECT_FALSE(with_nan.finite);
    EXPECT_EQ(with_nan.max_contour_error, 0.0);  // the other samples are on the path
    samples[4].position(7) = 0.0;
    samples[9].position(0) = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(measure(samples, points, sample_period).finite);
}

TEST(MeasureEdge, RepeatedPointsAreIgnored) {
    const double r = 0.5;
    const auto samples = timed(test::filleted({axes(-10, 0), axes(0, 0), axes(0, 10)}, {r}, 100, 500), sample_period);
    const std::vector<AxisVector> points{axes(-10, 0), axes(-10, 0), axes(0, 0), axes(0, 0),
                                         axes(0, 0),   axes(0, 10),  axes(0, 10)};
    const Measured m = measure(samples, points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_NEAR(m.corner_errors[0], r * (std::numbers::sqrt2 - 1.0), 1e-9);
    EXPECT_NEAR(m.max_contour_error, r * (1.0 - 1.0 / std::numbers::sqrt2), 1e-9);
}

TEST(MeasureEdge, FewSamples) {
    const std::vector<AxisVector> points{axes(0), axes(5), axes(5, 5)};
    const Measured none = measure({}, points, sample_period);
    EXPECT_EQ(none.cycle_time, 0.0);
    EXPECT_TRUE(none.end_position.isZero());
    EXPECT_TRUE(none.corner_errors.empty());

    AxisState one;
    one.time = 0.5;
    one.position = axes(1, 2, 3);
    const Measured single = measure(std::vector<AxisState>{one}, points, sample_period);
    EXPECT_EQ(single.cycle_time, 0.5);
    EXPECT_EQ(single.end_position, axes(1, 2, 3));
    EXPECT_EQ(single.max_contour_error, 0.0);
    EXPECT_EQ(single.max_corner_error, 0.0);
    EXPECT_TRUE(single.max_velocity.isZero());
    EXPECT_TRUE(single.finite);
}

TEST(MeasureEdge, OvershootPastTheEndIsMeasuredToTheEndPoint) {
    const std::vector<AxisVector> points{axes(0, 0), axes(10, 0)};
    const Measured m = measure(timed(on_polyline({axes(0, 0), axes(12, 0)}, 120), sample_period), points, sample_period);
    EXPECT_NEAR(m.max_contour_error, 2.0, 1e-12);
}

TEST(MeasureEdge, LongProgram) {
    // 10^4 zigzag segments, 10^5 samples on them.
    std::vector<AxisVector> points;
    for (int k = 0; k <= 10000; ++k) points.push_back(axes(0.1 * k, (k % 2) * 0.05, (k % 3) * 0.02));
    const Measured m = measure(timed(on_polyline(points, 10), sample_period), points, sample_period);
    EXPECT_EQ(m.corner_errors.size(), 9999u);
    EXPECT_LT(m.max_corner_error, 1e-9);
    EXPECT_LT(m.max_contour_error, 1e-9);
}

}  // namespace
}  // namespace firtp
