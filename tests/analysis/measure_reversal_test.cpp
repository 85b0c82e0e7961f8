// Reversals: the path comes back over itself, so only forward tracking tells the visits apart.
#include "trajectories.hpp"

#include <firtp/measure.hpp>

#include <gtest/gtest.h>

namespace firtp {
namespace {

using test::sample_period;
using test::append_dwell;
using test::append_line;
using test::timed;

// Positions base + s * direction for a 1-D profile s that turns short of each programmed end.
std::vector<AxisVector> along(const AxisVector& base, const AxisVector& direction, const std::vector<double>& stops) {
    std::vector<AxisVector> out;
    for (std::size_t k = 0; k + 1 < stops.size(); ++k) {
        append_dwell(out, base + stops[k] * direction, 5);
        append_line(out, base + stops[k] * direction, base + stops[k + 1] * direction, 97);
    }
    append_dwell(out, base + stops.back() * direction, 5);
    return out;
}

TEST(MeasureReversal, OutAndBackUndershoot) {
    const AxisVector x = test::axes(1);
    const std::vector<AxisVector> points{test::axes(0), test::axes(10), test::axes(0)};
    const Measured m = measure(timed(along(AxisVector::Zero(), x, {0.0, 9.7, 0.0}), sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 1u);
    EXPECT_NEAR(m.corner_errors[0], 0.3, 1e-12);
    EXPECT_NEAR(m.max_contour_error, 0.0, 1e-12);
}

TEST(MeasureReversal, OutBackOutSeparatesTheVisits) {
    // The start sample sits on the second turn point and the last one on the first: neither counts.
    const std::vector<AxisVector> points{test::axes(0), test::axes(10), test::axes(0), test::axes(10)};
    const Measured m =
        measure(timed(along(AxisVector::Zero(), test::axes(1), {0.0, 9.7, 0.2, 10.0}), sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 2u);
    EXPECT_NEAR(m.corner_errors[0], 0.3, 1e-12);
    EXPECT_NEAR(m.corner_errors[1], 0.2, 1e-12);
    EXPECT_NEAR(m.max_corner_error, 0.3, 1e-12);
}

TEST(MeasureReversal, Oblique9AxisReversals) {
    AxisVector base;
    base << 1.1, 2.2, -3.3, 40.4, 5.5, -6.6, 7.7, 8.8, 0.9;
    AxisVector direction;
    direction << 0.3, -0.7, 0.1, 0.2, 0, 0, 0.5, 0, -0.4;
    direction.normalize();
    const std::vector<AxisVector> points{base, base + 10.0 * direction, base, base + 10.0 * direction, base};
    const Measured m = measure(timed(along(base, direction, {0.0, 9.6, 0.25, 9.9, 0.0}), sample_period), points, sample_period);
    ASSERT_EQ(m.corner_errors.size(), 3u);
    EXPECT_NEAR(m.corner_errors[0], 0.4, 1e-9);
    EXPECT_NEAR(m.corner_errors[1], 0.25, 1e-9);
    EXPECT_NEAR(m.corner_errors[2], 0.1, 1e-9);
    EXPECT_NEAR(m.max_contour_error, 0.0, 1e-9);
}

}  // namespace
}  // namespace firtp
