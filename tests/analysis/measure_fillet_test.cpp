// Corner and contour errors of circular fillets, whose geometry is known exactly.
#include "trajectories.hpp"

#include <firtp/measure.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace firtp {
namespace {

using test::sample_period;
using test::axes;
using test::filleted;
using test::timed;

const double sqrt2 = std::numbers::sqrt2;

TEST(MeasureFillet, DenseSamplesGiveExactErrorsAtRightAngle) {
    const std::vector<AxisVector> points{axes(-10, 0), axes(0, 0), axes(0, 10)};
    const double r = 0.5;
    const auto samples = timed(filleted(points, {r}, 200, 1000), sample_period);
    const Measured m = measure(samples, points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_NEAR(m.corner_errors[0], r * (sqrt2 - 1.0), 1e-9);
    EXPECT_NEAR(m.max_corner_error, r * (sqrt2 - 1.0), 1e-9);
    // The arc's middle is farthest from the legs, measured perpendicular to them.
    EXPECT_NEAR(m.max_contour_error, r * (1.0 - 1.0 / sqrt2), 1e-9);
}

TEST(MeasureFillet, CoarseSamplesStayWithinSamplingBound) {
    const std::vector<AxisVector> points{axes(-10, 0), axes(0, 0), axes(0, 10)};
    const double r = 0.5;
    const double turn = std::numbers::pi / 2.0;
    const int arc_steps = 3;  // no sample at the arc's middle
    const auto samples = timed(filleted(points, {r}, 5, arc_steps), sample_period);
    const Measured m = measure(samples, points, sample_period);

    // Nearest sample is half a step away from the arc's middle.
    const double half_step = turn / arc_steps / 2.0;
    const double center_to_corner = r * sqrt2;
    const double corner_bound =
        std::sqrt(center_to_corner * center_to_corner + r * r - 2.0 * center_to_corner * r * std::cos(half_step));
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_GE(m.corner_errors[0], r * (sqrt2 - 1.0) - 1e-12);
    EXPECT_LE(m.corner_errors[0], corner_bound + 1e-12);
    EXPECT_GT(m.corner_errors[0], r * (sqrt2 - 1.0) + 1e-3);  // really coarse

    EXPECT_LE(m.max_contour_error, r * (1.0 - 1.0 / sqrt2) + 1e-12);
    EXPECT_GE(m.max_contour_error, r * (1.0 - std::cos(turn / 2.0 - half_step)) - 1e-12);
}

TEST(MeasureFillet, UsesAllNineAxes) {
    // A 60 degree turn in a plane spanned by Y Z A C V W, away from the origin.
    AxisVector e1;
    e1 << 0, 0, 1, 0, 0, 1, 0, 0, 1;
    AxisVector e2;
    e2 << 0, 1, 0, 1, 0, 0, 0, -1, 0;
    e1 /= std::sqrt(3.0);
    e2 /= std::sqrt(3.0);
    AxisVector origin;
    origin << 1, 2, 3, 4, 5, 6, 7, 8, 9;
    const std::vector<AxisVector> points{origin - 10.0 * e1, origin,
                                         origin + 10.0 * (0.5 * e1 + std::sqrt(3.0) / 2.0 * e2)};
    const double r = 2.0;
    const auto samples = timed(filleted(points, {r}, 100, 2000), sample_period);
    const Measured m = measure(samples, points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_NEAR(m.corner_errors[0], r * (2.0 / std::sqrt(3.0) - 1.0), 1e-9);
    EXPECT_NEAR(m.max_contour_error, r * (1.0 - std::sqrt(3.0) / 2.0), 1e-9);
}

TEST(MeasureFillet, DiamondCornersAreMeasuredSeparately) {
    // Starts in the middle of an edge and returns there: four corners, each with its own radius.
    const AxisVector start = axes(5, -5);
    const std::vector<AxisVector> points{start, axes(10, 0), axes(0, 10), axes(-10, 0), axes(0, -10), start};
    const std::vector<double> radii{0.4, 0.1, 0.3, 0.2};
    const Measured m = measure(timed(filleted(points, radii, 300, 400), sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 4u);
    for (std::size_t j = 0; j < radii.size(); ++j) EXPECT_NEAR(m.corner_errors[j], radii[j] * (sqrt2 - 1.0), 1e-9) << j;
    EXPECT_NEAR(m.max_corner_error, 0.4 * (sqrt2 - 1.0), 1e-9);
    EXPECT_NEAR(m.max_contour_error, 0.4 * (1.0 - 1.0 / sqrt2), 1e-9);
}

TEST(MeasureFillet, DiamondFromVertexHasNoCornerAtStart) {
    const std::vector<AxisVector> points{axes(10, 0), axes(0, 10), axes(-10, 0), axes(0, -10), axes(10, 0)};
    const std::vector<double> radii{0.3, 0.1, 0.2};
    const Measured m = measure(timed(filleted(points, radii, 300, 400), sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 3u);
    for (std::size_t j = 0; j < radii.size(); ++j) EXPECT_NEAR(m.corner_errors[j], radii[j] * (sqrt2 - 1.0), 1e-9) << j;
}

TEST(MeasureFillet, RevisitedCornersAreMeasuredPerVisit) {
    // Two laps from a sharp start at a vertex: the start vertex becomes a rounded corner in the
    // middle, and every vertex is rounded differently on each lap.
    const AxisVector v0 = axes(10, 0), v1 = axes(0, 10), v2 = axes(-10, 0), v3 = axes(0, -10);
    const std::vector<AxisVector> points{v0, v1, v2, v3, v0, v1, v2, v3, v0};
    const std::vector<double> radii{0.5, 0.1, 0.6, 0.3, 0.2, 0.7, 0.4};
    const Measured m = measure(timed(filleted(points, radii, 300, 400), sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 7u);
    for (std::size_t j = 0; j < radii.size(); ++j) EXPECT_NEAR(m.corner_errors[j], radii[j] * (sqrt2 - 1.0), 1e-9) << j;
    EXPECT_NEAR(m.max_contour_error, 0.7 * (1.0 - 1.0 / sqrt2), 1e-9);
}

}  // namespace
}  // namespace firtp
