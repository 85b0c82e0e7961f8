// Forward tracking of the samples along the programmed segments.
#include "trajectories.hpp"

#include <firtp/measure.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace firtp {
namespace {

using test::sample_period;
using test::append_line;
using test::axes;
using test::timed;

TEST(MeasureTracking, CuttingAcrossASpikeDoesNotStall) {
    // The program makes a 5 mm spike; the tool goes straight on along X and then turns up at 20.
    const std::vector<AxisVector> points{axes(0, 0), axes(10, 0), axes(10, 5), axes(10.1, 0), axes(20, 0), axes(20, 10)};
    std::vector<AxisVector> path;
    append_line(path, axes(0, 0), axes(20, 0), 400);  // 0.05 apart: one sample inside the spike's base
    append_line(path, axes(20, 0), axes(20, 10), 200);
    path.push_back(axes(20, 10));
    const Measured m = measure(timed(path, sample_period), points, sample_period);

    // Only x = 10.05 leaves the program: 0.05 from X = 10, slightly less from the spike's far side.
    EXPECT_NEAR(m.max_contour_error, 5.0 * 0.05 / std::sqrt(25.01), 1e-9);
    ASSERT_EQ(m.corner_errors.size(), 4u);
    EXPECT_LT(m.corner_errors[0], 1e-9);
    // The spike's tip: at least 5 away, at most as far as the sample inside the spike's base.
    EXPECT_GE(m.corner_errors[1], 5.0 - 1e-9);
    EXPECT_LE(m.corner_errors[1], std::hypot(0.05, 5.0) + 1e-9);
    EXPECT_LT(m.corner_errors[2], 1e-9);
    EXPECT_LT(m.corner_errors[3], 1e-9);
}

TEST(MeasureTracking, SampleFallingBackIsMeasuredToTheEarlierSegment) {
    // After reaching the second segment one sample falls back beside the first one, 0.3 from it
    // but 0.58 from the second.
    const std::vector<AxisVector> points{axes(0, 0), axes(10, 0), axes(10, 10)};
    std::vector<AxisVector> path;
    append_line(path, axes(0, 0), axes(10, 0), 100);
    append_line(path, axes(10, 0), axes(10, 0.5), 5);
    path.push_back(axes(9.5, -0.3));
    append_line(path, axes(10, 0.5), axes(10, 10), 100);
    path.push_back(axes(10, 10));
    const Measured m = measure(timed(path, sample_period), points, sample_period);
    EXPECT_NEAR(m.max_contour_error, 0.3, 1e-12);
}

TEST(MeasureTracking, UnreachedCornersUseTheLastSample) {
    // The samples stop 4 along the second segment: the corners after it were never reached.
    const std::vector<AxisVector> points{axes(0, 0), axes(10, 0), axes(10, 10), axes(0, 10), axes(0, 20)};
    std::vector<AxisVector> path;
    append_line(path, axes(0, 0), axes(10, 0), 50);
    append_line(path, axes(10, 0), axes(10, 4), 20);
    path.push_back(axes(10, 4));
    const Measured m = measure(timed(path, sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 3u);
    EXPECT_LT(m.corner_errors[0], 1e-12);
    EXPECT_NEAR(m.corner_errors[1], 6.0, 1e-12);
    EXPECT_NEAR(m.corner_errors[2], std::hypot(10.0, 6.0), 1e-12);
    EXPECT_NEAR(m.max_corner_error, std::hypot(10.0, 6.0), 1e-12);
}

}  // namespace
}  // namespace firtp
