// The plot's bounded view of the samples: every row while there are few, a bounded number after,
// and the extremes (a one-sample spike) always among them; zooms on the largest corner errors.
#include "plot_samples.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace firtp::cli {
namespace {

TEST(MinMaxDecimation, KeepsEveryRowWhileThereAreFew) {
    MinMaxDecimation<2> d(100);
    for (int i = 0; i < 100; ++i) d.add({static_cast<double>(i), std::sin(i)});
    const auto rows = d.rows();
    ASSERT_EQ(rows.size(), 100u);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(rows[static_cast<std::size_t>(i)][0], i);
}

TEST(MinMaxDecimation, BoundedAndKeepsTheSpikes) {
    MinMaxDecimation<2> d(1000);
    const std::size_t n = 2'000'003;
    for (std::size_t i = 0; i < n; ++i) {
        double y = std::sin(static_cast<double>(i) * 1e-4);
        if (i == 1'234'567) y = 50.0;   // one sample high
        if (i == 777'777) y = -40.0;    // one sample low
        d.add({static_cast<double>(i), y});
    }
    const auto rows = d.rows();
    EXPECT_LE(rows.size(), 1000u * 5 + 1);
    EXPECT_GE(rows.size(), 500u);
    EXPECT_TRUE(std::is_sorted(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; }));
    const auto has = [&](double x, double y) {
        return std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return r[0] == x && r[1] == y; });
    };
    EXPECT_TRUE(has(1'234'567, 50.0));
    EXPECT_TRUE(has(777'777, -40.0));
    EXPECT_EQ(rows.front()[0], 0.0);
    EXPECT_EQ(rows.back()[0], static_cast<double>(n - 1));  // the last sample
}

AxisState at(double x, double y) {
    AxisState s;
    s.position[0] = x;
    s.position[1] = y;
    return s;
}

TEST(PlotSamples, ZoomsOnTheFourLargestErrorsInProgramOrder) {
    PlotSamples plot;
    CornerReport corner;
    corner.beta = 1.0;
    corner.epsilon = 0.05;
    const double errors[] = {0.01, 0.04, 0.02, 0.04, 0.03, 0.005, 0.04};
    for (std::size_t i = 0; i < 7; ++i) {
        corner.point[0] = 10.0 * static_cast<double>(i);
        plot.add(at(corner.point[0], 0.0));          // passes the corner
        plot.add(at(corner.point[0] + 5.0, 0.0));    // and leaves its window
        plot.corner_error(i, errors[i], corner);
    }
    ASSERT_EQ(plot.zooms.size(), 4u);
    // 0.04 (1), 0.04 (3), 0.04 (6), 0.03 (4): the stable order of the largest, shown by index.
    EXPECT_EQ(plot.zooms[0].corner, 1u);
    EXPECT_EQ(plot.zooms[1].corner, 3u);
    EXPECT_EQ(plot.zooms[2].corner, 4u);
    EXPECT_EQ(plot.zooms[3].corner, 6u);
    for (const ZoomSamples& z : plot.zooms) {  // each caught its pass, looking back
        ASSERT_FALSE(z.xy.empty());
        EXPECT_EQ(z.xy.front()[0], z.centre[0]);
    }
}

}  // namespace
}  // namespace firtp::cli
