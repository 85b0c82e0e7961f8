// The measurement on dense CAM output (issue 14): narrow spikes of micrometre blocks, as V-carve
// and pocketing programs write them, where the tool cuts across the tip of each spike within its
// tolerance. component/analysis follows the samples along the path to attribute them to corners;
// it used to get stuck on one leg of such a spike and report errors of millimetres. Checked here
// against an independent measurement that follows nothing: for every programmed point, the
// closest approach of all the chords between consecutive samples (a lower bound of the
// attributed error, and the error itself where the path passes a point once).
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace firtp;

namespace {

AxisVector xy(double x, double y) {
    AxisVector v = AxisVector::Zero();
    v[0] = x, v[1] = y;
    return v;
}

double chord_distance(const AxisVector& point, const AxisVector& a, const AxisVector& b) {
    const AxisVector d = b - a;
    const double dd = d.squaredNorm();
    const double u = dd > 0.0 ? std::clamp((point - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    return (a + u * d - point).norm();
}

// Spikes up and down along X: each a parabola y = tip -/+ k (x - x_tip)^2 in steps of 2 um in X
// (chords of 2-80 um near the tip), the next spike 0.3 mm further on.
std::vector<Block> spikes(int count, double feed, double tolerance) {
    std::vector<Block> blocks;
    auto add = [&](const AxisVector& p) {
        Block b;
        b.target = p;
        b.feed = feed;
        b.tolerance = tolerance;
        b.line = static_cast<std::int64_t>(blocks.size()) + 1;
        blocks.push_back(b);
    };
    constexpr int steps = 40;
    constexpr double dx = 0.001963, k = 400.0;
    double x = 0.0;
    for (int s = 0; s < count; ++s) {
        const double sign = s % 2 == 0 ? 1.0 : -1.0;
        const double tip_x = x + steps * dx;
        for (int i = -steps; i <= steps; ++i) add(xy(tip_x + i * dx, sign * (2.5 - k * (i * dx) * (i * dx))));
        x = tip_x + steps * dx + 0.3;
        add(xy(x, sign * (2.5 - k * (steps * dx) * (steps * dx))));
    }
    return blocks;
}

}  // namespace

TEST(DenseMeasurement, SpikesOfMicrometreBlocksAreMeasuredAsTheChordsPassThem) {
    PlannerParameters p;
    for (int a = 0; a < 3; ++a) p.limits.axis[a] = {300.0, 5000.0, 1e5};
    for (const double feed : {400.0 / 60.0, 3000.0 / 60.0}) {
        const double tolerance = 0.05;
        const std::vector<Block> blocks = spikes(12, feed, tolerance);
        const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
        std::vector<AxisVector> points{AxisVector::Zero()};
        for (const Block& b : blocks) points.push_back(b.target);
        const Measured m = measure(t.samples, points, p.period);
        ASSERT_EQ(m.corner_errors.size(), points.size() - 2);
        double worst = 0.0, worst_independent = 0.0;
        for (std::size_t j = 1; j + 1 < points.size(); ++j) {
            double independent = HUGE_VAL;
            for (std::size_t i = 0; i + 1 < t.samples.size(); ++i)
                independent = std::min(independent, chord_distance(points[j], t.samples[i].position, t.samples[i + 1].position));
            const double measured = m.corner_errors[j - 1];
            SCOPED_TRACE("feed " + std::to_string(feed) + ", point " + std::to_string(j));
            EXPECT_LE(independent, tolerance * (1 + 1e-6));  // the tool passes every point within its tolerance
            EXPECT_GE(measured, independent - 1e-12);         // the attributed chords are some of all the chords
            EXPECT_LE(measured, tolerance * (1 + 1e-6));      // and the measurement says so
            worst = std::max(worst, measured);
            worst_independent = std::max(worst_independent, independent);
        }
        std::printf("feed %.1f mm/s: %zu points, worst corner error %.5f mm measured, %.5f mm by all chords (tolerance %.2f)\n",
                    feed, points.size() - 2, worst, worst_independent, tolerance);
    }
}
