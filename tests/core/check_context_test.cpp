// The check's context: the legs before the re-planned tail that it sums with it. A rapid's wide
// kernels reach far back only while they move; the dense run after it is checked over as few
// legs as the same run without the rapid. Limits, tolerance and end point measured on the samples.
#include "support/limits.hpp"
#include "support/reference.hpp"

#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace firtp;
using firtp::test::line_to;
using firtp::test::xyz;

namespace {

// 0.05 mm moves at 50 mm/s (one servo period each), turning 8 degrees either way, 0.01 mm
// tolerance: CAM output finer than the period.
std::vector<Block> dense_run(const AxisVector& from, int moves, std::int64_t line) {
    std::vector<Block> blocks;
    AxisVector at = from;
    for (int i = 0; i < moves; ++i) {
        const double angle = (i % 2 == 0 ? 4.0 : -4.0) * std::acos(-1.0) / 180.0;
        at += xyz(std::cos(angle), std::sin(angle)) * 0.05;
        blocks.push_back(line_to(at, 50.0, 0.01, line + i));
    }
    return blocks;
}

struct Planned {
    Trajectory t;
    double legs_per_check = 0.0;
};

Planned plan(const PlannerParameters& p, const AxisVector& start, const std::vector<Block>& blocks) {
    Planned r;
    r.t = plan_trajectory(p, start, blocks);
    r.legs_per_check = static_cast<double>(r.t.stats.legs_checked) / static_cast<double>(r.t.stats.checks);
    std::vector<AxisVector> points{start};
    for (const Block& b : blocks) points.push_back(b.target);
    const Measured m = measure(r.t.samples, points, p.period);
    EXPECT_LE(test::worst_ratio(r.t.samples, p.limits), 1.0 + 1e-6);
    for (int a = 0; a < 3; ++a) {  // 1 ms finite differences, as a drive sees them
        EXPECT_LE(m.max_velocity[a], p.limits.axis[a].max_velocity * (1 + 1e-6));
        EXPECT_LE(m.max_acceleration[a], p.limits.axis[a].max_acceleration * (1 + 1e-6));
        EXPECT_LE(m.max_jerk[a], p.limits.axis[a].max_jerk * (1 + 1e-6));
    }
    EXPECT_EQ(m.end_position, blocks.back().target);
    EXPECT_EQ(r.t.stats.unfit, 0u);
    return r;
}

}  // namespace

TEST(CheckContext, ARapidsWideKernelsNoLongerWidenTheDenseRunsChecksOnceSettled) {
    PlannerParameters p;
    p.period = 0.001;
    p.limits = test::uniform_limits(300, 5000, 1e5);
    const AxisVector corner = xyz(150, 0);
    Block rapid = line_to(corner, 300.0, 0.01, 1, Termination::exact_stop);
    rapid.type = MotionType::traverse;
    std::vector<Block> with_rapid{rapid};
    const std::vector<Block> run = dense_run(corner, 4000, 2);
    with_rapid.insert(with_rapid.end(), run.begin(), run.end());
    const Planned a = plan(p, AxisVector::Zero(), with_rapid);
    const Planned b = plan(p, corner, run);
    std::printf("legs a check: after a rapid %.1f, alone %.1f (checks %llu, %llu)\n", a.legs_per_check, b.legs_per_check,
                static_cast<unsigned long long>(a.t.stats.checks), static_cast<unsigned long long>(b.t.stats.checks));
    // A context two rapid kernels wide (0.1 s and more) would sum over 100 more legs a check.
    EXPECT_LE(a.legs_per_check, 1.25 * b.legs_per_check);
    // And the run itself plans the same after the rapid as alone: the same time once at speed.
    EXPECT_NEAR(a.t.corners.back().speed_in, b.t.corners.back().speed_in, 1e-9);
}
