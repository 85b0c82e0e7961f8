// The paper's fixed chain: feed override, hold and abort scale the chain's clock. The tool stays
// on the planned path, stops within the ramp and ends exactly where commanded; an abort drops the
// rest of the program.
#include "support/reference.hpp"

#include <firtp/measure.hpp>
#include <firtp/planner.hpp>
#include <firtp/time_scale.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

using namespace firtp;
using firtp::test::xyz;

namespace {

struct Machine {
    PlannerParameters parameters;
    Planner planner;
    std::vector<AxisState> samples;
    std::vector<AxisVector> points{AxisVector::Zero()};

    Machine() : parameters(make_parameters()), planner(parameters, AxisVector::Zero()) {}
    static PlannerParameters make_parameters() {
        PlannerParameters p;
        p.fixed_chain = true;
        p.filters = test::chain_of({0.06, 0.02});
        p.period = 0.001;
        p.queue_capacity = 64;
        return p;
    }
    void add(const AxisVector& target, double feed = 100.0) {
        Block b;
        b.target = target;
        b.feed = feed;
        b.tolerance = 0.05;
        b.line = static_cast<std::int64_t>(points.size());
        ASSERT_EQ(planner.add(b), Result::ok);
        points.push_back(target);
    }
    // Ticks until idle (or max), calling `each` before every tick.
    void run(int max_ticks, const std::function<void(int)>& each = {}) {
        for (int k = 0; k < max_ticks; ++k) {
            if (each) each(k);
            AxisState s;
            planner.tick(s);
            samples.push_back(s);
            if (planner.idle() && k > 0) break;
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
    half.planner.set_rate(0.5);
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
        if (k == 150) m.planner.set_rate(0.0);
        if (k == 600) m.planner.set_rate(1.0);
        if (k > 150 && k < 600 && stopped_at < 0 && m.planner.time_scale().rate() == 0.0) stopped_at = k;
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
        if (k == 100) m.planner.abort();
    });
    ASSERT_TRUE(m.planner.idle());
    ASSERT_TRUE(m.planner.take_flushed());
    const AxisVector stopped = m.planner.rest_position();
    EXPECT_GT(stopped[0], 0.0);
    EXPECT_LT(stopped[0], 30.0);
    EXPECT_NEAR(stopped[1], 0.0, 1e-12);  // on the first block's line
    EXPECT_EQ(m.planner.goal(), stopped);  // it plans afresh from there
    m.samples.clear();
    m.points = {stopped};
    m.add(xyz(0, 0));
    m.run(100000);
    EXPECT_EQ(m.samples.back().position, xyz(0, 0));
    for (const AxisState& s : m.samples) EXPECT_NEAR(s.position[1], 0.0, 1e-12);  // never went on to Y30
}

// A trim loses exactly the fraction asked, within half the rate limits, and ends at rate 1.
TEST(TimeScale, TrimLosesTheFractionAlongADipWithinHalfTheRateLimits) {
    for (const RateLimits limits : {RateLimits{}, RateLimits{0.8, 12.0}}) {
        for (const double fraction : {1e-6, 0.25, 0.999}) {
            TimeScale scale(limits);
            scale.trim(fraction, 0.001);
            double clock = 0.0, slope = 0.0, curvature = 0.0;
            int ticks = 0;
            for (; ticks < 100000 && (ticks == 0 || !scale.steady_at_one()); ++ticks) {
                clock += scale.advance(0.001);
                slope = std::max(slope, std::abs(scale.slope()));
                curvature = std::max(curvature, std::abs(scale.curvature()));
                ASSERT_LE(scale.rate(), 1.0);
            }
            EXPECT_NEAR(clock, ticks - fraction, 1e-12) << fraction;
            EXPECT_LE(slope, 0.5 * limits.max_slope * 1.001);
            EXPECT_LE(curvature, 0.5 * limits.max_curvature * 1.05);  // r'' is a difference of r' a period apart
            EXPECT_EQ(scale.rate(), 1.0);
        }
    }
}

// After an override or a hold the filters' clock is a fraction of a period off the servo samples;
// at rate 1 a trim brings it back, so the samples are again those the planner checked: the rest of
// the program equals the plan without the change, a whole number of periods later. (Off the grid
// the straight lines between samples cut a tight corner differently: 1.0011 of its tolerance was
// measured in LcmFaults.LossyLink with another seed.)
TEST(TimeScale, AfterAnOverrideOrAHoldTheSamplesComeBackOntoThePlannedGrid) {
    auto program = [](Machine& m) {
        for (int i = 0; i < 40; ++i) m.add(xyz(10.0 * (i + 1), i % 2 == 0 ? 5.0 : 0.0), 150.0);
    };
    Machine plain;
    program(plain);
    plain.run(100000);
    struct Change { double rate; int from, to; };
    for (const Change change : {Change{0.37, 500, 1234}, Change{0.0, 500, 530}, Change{0.0, 500, 1234}}) {
        Machine changed;
        program(changed);
        changed.run(100000, [&](int k) {
            if (k == change.from) changed.planner.set_rate(change.rate);
            if (k == change.to) changed.planner.set_rate(1.0);
        });
        ASSERT_EQ(changed.samples.back().position, plain.samples.back().position);
        // The last 1,500 samples (after the ramp and the trim): plain's, a whole number of periods later.
        const std::size_t shift = changed.samples.size() - plain.samples.size();
        double worst = 0.0;
        for (std::size_t k = plain.samples.size() - 1500; k < plain.samples.size(); ++k)
            worst = std::max(worst, (changed.samples[k + shift].position - plain.samples[k].position).cwiseAbs().maxCoeff());
        EXPECT_LT(worst, 1e-9) << change.rate << " from " << change.from << " to " << change.to;
        std::printf("rate %.2f from tick %d to %d: the rest runs %zu periods later, %.2g mm from the plan's samples\n",
                    change.rate, change.from, change.to, shift, worst);
    }
}
