// Feed override, hold and abort: the tool stays on the planned path, stops within the ramp and
// ends exactly where commanded; an abort drops the rest of the program.
#include "support/reference.hpp"

#include <firtp/interpolator.hpp>
#include <firtp/measure.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace firtp;
using firtp::test::xyz;

namespace {

struct Machine {
    PlannerParameters parameters;
    FirChain chain;
    Interpolator interpolator;
    Planner planner;
    std::vector<AxisState> samples;
    std::vector<AxisVector> points{AxisVector::Zero()};

    Machine()
        : parameters(make_parameters()), chain(parameters.filters),
          interpolator(chain, parameters.period, 64, AxisVector::Zero()),
          planner(parameters, chain, AxisVector::Zero()) {}
    static PlannerParameters make_parameters() {
        PlannerParameters p;
        p.filters = test::chain_of({0.06, 0.02});
        p.period = 0.001;
        return p;
    }
    void add(const AxisVector& target, double feed = 100.0) {
        Block b;
        b.target = target;
        b.feed = feed;
        b.tolerance = 0.05;
        b.line = static_cast<std::int64_t>(points.size());
        ASSERT_EQ(planner.add(b, interpolator), Result::ok);
        points.push_back(target);
    }
    // Ticks until idle (or max), calling `each` before every tick.
    void run(int max_ticks, const std::function<void(int)>& each = {}) {
        for (int k = 0; k < max_ticks; ++k) {
            if (each) each(k);
            AxisState s;
            interpolator.tick(s);
            samples.push_back(s);
            if (interpolator.idle() && k > 0) break;
        }
    }
};

}  // namespace

TEST(TimeScale, HalfFeedFollowsTheSamePathAndEndsExactly) {
    Machine full, half;
    for (Machine* m : {&full, &half}) {
        m->add(xyz(20, 0));
        m->add(xyz(20, 15));
        m->add(xyz(0, 15));
    }
    full.run(100000);
    half.interpolator.set_rate(0.5);
    half.run(100000);
    const Measured f = measure(full.samples, full.points, 0.001), h = measure(half.samples, half.points, 0.001);
    EXPECT_EQ(h.end_position, xyz(0, 15));
    EXPECT_NEAR(h.max_contour_error, f.max_contour_error, 1e-3);
    for (std::size_t c = 0; c < f.corner_errors.size(); ++c) EXPECT_NEAR(h.corner_errors[c], f.corner_errors[c], 2e-3);
    EXPECT_NEAR(h.max_path_speed, 0.5 * f.max_path_speed, 0.02 * f.max_path_speed);
    EXPECT_NEAR(h.cycle_time, 2 * f.cycle_time, 0.15);  // plus the ramp from 1 to 0.5
}

TEST(TimeScale, HoldStopsOnThePathWithinTheRampAndResumes) {
    Machine m;
    m.add(xyz(30, 0));
    m.add(xyz(30, 30));
    int stopped_at = -1;
    AxisVector held;
    m.run(100000, [&](int k) {
        if (k == 150) m.interpolator.set_rate(0.0);
        if (k == 600) m.interpolator.set_rate(1.0);
        if (k > 150 && k < 600 && stopped_at < 0 && m.interpolator.time_scale().rate() == 0.0) stopped_at = k;
    });
    ASSERT_GT(stopped_at, 0);
    // Full rate to 0 within the S-curve's stop time (0.25 s without axis limits).
    EXPECT_LE(stopped_at - 150, std::ceil(stop_time(RateLimits{}, 1.0) / 0.001) + 1);
    held = m.samples[stopped_at + 1].position;
    for (int k = stopped_at + 1; k < 600; ++k) {
        EXPECT_EQ(m.samples[k].position, held);
        EXPECT_EQ(m.samples[k].velocity, AxisVector::Zero());
    }
    const Measured measured = measure(m.samples, m.points, 0.001);
    EXPECT_LE(measured.max_corner_error, 0.05);
    EXPECT_EQ(measured.end_position, xyz(30, 30));
}

TEST(TimeScale, AbortStopsDropsTheRestAndPlansAfreshFromThere) {
    Machine m;
    m.add(xyz(30, 0));
    m.add(xyz(30, 30));
    m.add(xyz(0, 30));
    m.run(400, [&](int k) {
        if (k == 100) {
            m.interpolator.set_rate(0.0);
            m.interpolator.abort();
        }
    });
    ASSERT_TRUE(m.interpolator.idle());
    ASSERT_TRUE(m.interpolator.take_flushed());
    const AxisVector stopped = m.interpolator.rest_position();
    EXPECT_GT(stopped[0], 0.0);
    EXPECT_LT(stopped[0], 30.0);
    EXPECT_NEAR(stopped[1], 0.0, 1e-12);  // on the first block's line
    m.planner.reset(stopped, m.interpolator.now_tick());
    m.interpolator.set_rate(1.0);
    m.samples.clear();
    m.points = {stopped};
    m.add(xyz(0, 0));
    m.run(100000);
    EXPECT_EQ(m.samples.back().position, xyz(0, 0));
    for (const AxisState& s : m.samples) EXPECT_NEAR(s.position[1], 0.0, 1e-12);  // never went on to Y30
}
