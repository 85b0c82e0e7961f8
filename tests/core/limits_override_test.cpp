// Feed override, hold, resume and abort at random moments while smoothing at the limits (the
// default mode, no rate reserve): random machines and programs from support/random_machine.hpp,
// rates up to MAX_FEED_OVERRIDE changed at random ticks. Measured on the samples:
// - axis velocity, acceleration and jerk within the limits at every sample and as finite
//   differences of the positions (what a drive sees);
// - every blended corner within its tolerance, whatever the rate did (each rate is planned and
//   checked as its own motion);
// - the end exactly on the last point; an abort rests on the path and runs nothing after it;
// - a hold or an abort comes to rest within hold_time_bound(): the step under way ends, and one
//   more step brings the axes from the highest speed to rest.
// Seeded; FIRTP_RANDOM_SEED shifts the seeds and FIRTP_RANDOM_SCALE soaks.
#include "support/random_machine.hpp"
#include "support/rate_run.hpp"
#include "support/sampled_limits.hpp"

#include <firtp/measure.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace firtp;

namespace {

// Six rate changes at random ticks within `moving` ticks, then 1 (or an abort); the draws do not
// depend on `moving`, so a program of the sequence can be reached without running those before it.
std::vector<std::pair<int, double>> rate_events(std::mt19937_64& rng, int moving, const PlannerParameters& p,
                                                bool holds_asked, int k) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::pair<int, double>> events;
    int tick = 0;
    for (int e = 0; e < 6; ++e) {
        tick += 1 + static_cast<int>(unit(rng) * moving / 4);
        const double u = unit(rng);
        events.emplace_back(tick, holds_asked && u < 0.3 ? 0.0 : u < 0.5 ? p.max_rate : p.max_rate * (0.05 + 0.95 * unit(rng)));
    }
    events.emplace_back(tick + 1 + static_cast<int>(unit(rng) * moving / 4), holds_asked && k % 4 == 3 ? -1.0 : 1.0);
    return events;
}

// `holds`: rate 0 (hold), resumes and aborts among the rate changes.
// `jerk`: check the jerk limit too. `only` >= 0: that program of the sequence alone.
void check_rate_changes(std::uint64_t seed, int count, bool holds_asked, bool jerk, int only = -1) {
    std::mt19937_64 rng(seed + (only >= 0 ? 0 : test::random_seed_offset()));
    const int programs = only >= 0 ? only + 1 : test::random_scaled(count);
    double worst = 0.0, worst_corner = 0.0, worst_stop = 0.0;
    int holds = 0, aborts = 0, failed = 0;
    for (int k = 0; k < programs; ++k) {
        test::RandomCase c = test::random_case(rng);
        const PlannerParameters& p = c.parameters;
        if (k < only) {
            rate_events(rng, 0, p, holds_asked, k);
            continue;
        }
        const test::RateRun reference = test::run_with_rates(p, c.blocks, {});
        const std::vector<std::pair<int, double>> events =
            rate_events(rng, static_cast<int>(reference.samples.size()), p, holds_asked, k);
        const test::RateRun r = test::run_with_rates(p, c.blocks, events);
        SCOPED_TRACE("program " + std::to_string(k));
        const int parts_before = ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
        [&] {  // every program is checked; its first failure ends its checks
            ASSERT_FALSE(r.samples.empty());
            const Measured m = measure(r.samples, r.points, p.period);
            ASSERT_TRUE(m.finite);
            ASSERT_EQ(test::beyond_limits(r.samples, m, p, jerk), "");
            for (int a = 0; a < p.limits.axes; ++a) worst = std::max(worst, m.max_acceleration[a] / p.limits.axis[a].max_acceleration);
            ASSERT_EQ(r.samples.back().velocity, AxisVector::Zero());
            const double bound = hold_time_bound(p) + 2 * p.period;
            ASSERT_LE(r.longest_stop, bound);
            worst_stop = std::max(worst_stop, r.longest_stop / bound);
            if (r.aborted) {  // on the path (within the widest tolerance), nothing after the abort
                ++aborts;
                double widest = 0.0;
                for (const Block& b : c.blocks) widest = std::max(widest, b.tolerance);
                ASSERT_LE(m.max_contour_error, widest * (1 + 1e-6) + 1e-9);
                return;
            }
            if (r.longest_stop > 0.0) ++holds;
            ASSERT_EQ(m.end_position, c.blocks.back().target);  // exact
            // Corner errors: blended corners within their tolerance at whatever rate they ran.
            std::vector<AxisVector> points{AxisVector::Zero()};
            std::vector<const Block*> ending;
            for (const Block& b : c.blocks)
                if ((b.target - points.back()).norm() >= min_block_length) points.push_back(b.target), ending.push_back(&b);
            const Measured mc = measure(r.samples, points, p.period);
            ASSERT_EQ(mc.corner_errors.size(), points.size() < 2 ? 0u : points.size() - 2);
            for (std::size_t i = 0; i < mc.corner_errors.size(); ++i) {
                const Block& b = *ending[i];
                const AxisVector in = points[i + 1] - points[i], out = points[i + 2] - points[i + 1];
                if (b.termination != Termination::blend || in.normalized().dot(out.normalized()) > 1.0 - 1e-12) continue;
                ASSERT_LE(mc.corner_errors[i], b.tolerance * (1 + 1e-6) + 1e-9) << "corner after line " << b.line;
                worst_corner = std::max(worst_corner, mc.corner_errors[i] / b.tolerance);
            }
        }();
        if (::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count() > parts_before) ++failed;
    }
    if (only >= 0) return;  // one program: its checks are the test
    if (holds_asked) {
        EXPECT_GT(holds, 10);
        EXPECT_GT(aborts, 10);
    }
    EXPECT_GT(worst, 0.95);  // the limits are reached, not only respected from afar
    std::printf("%d programs with rate changes (%d failed): worst |a| / limit %.4f, corner error / tolerance %.4f; "
                "%d holds and %d aborts, longest stop %.2f of its bound\n",
                programs, failed, worst, worst_corner, holds, aborts, worst_stop);
}

}  // namespace

// A hold in a block that ends in a stop (the program's last, or before an exact stop) stops inside
// the block, within hold_time_bound(), not at the block's end (it used to run on to the end: 2 s
// for this 200 mm block); resumed, the block ends exactly on its target.
TEST(Hold, InsideABlockThatEndsInAStop) {
    PlannerParameters p;
    p.limits.axes = 3;
    for (int a = 0; a < 3; ++a) p.limits.axis[a] = {300.0, 5000.0, 1e5};
    p.max_rate = 1.0;
    for (const bool exact : {false, true}) {
        SCOPED_TRACE(exact ? "exact stop, then a block" : "the last block");
        std::vector<Block> blocks(1);
        blocks[0].target = AxisVector::Zero();
        blocks[0].target[0] = 200.0;
        blocks[0].feed = 100.0;
        blocks[0].tolerance = 0.05;
        blocks[0].line = 1;
        if (exact) {
            blocks[0].termination = Termination::exact_stop;
            blocks.push_back(blocks[0]);
            blocks[1].target[1] = 50.0;
            blocks[1].line = 2;
        }
        const test::RateRun r = test::run_with_rates(p, blocks, {{500, 0.0}, {3000, 1.0}});  // hold at 0.5 s, 100 mm before the stop
        ASSERT_GT(r.longest_stop, 0.0);
        EXPECT_LE(r.longest_stop, hold_time_bound(p) + 2 * p.period);
        const AxisState& held = r.samples[2999];
        EXPECT_EQ(held.velocity, AxisVector::Zero());
        EXPECT_LT(held.position[0], 100.0);  // stopped inside the block, far from its end
        EXPECT_EQ(held.position[1], 0.0);
        const Measured m = measure(r.samples, r.points, p.period);
        EXPECT_EQ(m.end_position, blocks.back().target);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(m.max_velocity[a], 300.0 * (1 + 1e-6));
            EXPECT_LE(m.max_acceleration[a], 5000.0 * (1 + 1e-6));
            EXPECT_LE(m.max_jerk[a], 1e5 * (1 + 1e-6));
        }
    }
}

// Override changes (no hold): velocity, acceleration and jerk (at the samples and in the finite
// differences), every corner and the exact end hold on every program.
TEST(RandomMachines, OverrideChangesKeepLimitsToleranceAndEnd) { check_rate_changes(31, 120, false, true); }

// Holds, resumes and aborts among the rate changes: limits (also in finite differences), corner
// errors, the exact end and the stop bound on every program. A hold's braking or a resume that
// fails its check keeps the accepted plan and is tried again at the next tick (it used to run an
// unchecked plan whose legs no longer covered their blocks: position jumps of up to 15 mm at rest).
// Soaked with FIRTP_RANDOM_SEED=0..6 and FIRTP_RANDOM_SCALE=4 (20,160 programs): all pass.
TEST(RandomMachines, HoldResumeAndAbortKeepLimitsToleranceAndStopBound) { check_rate_changes(31, 120, true, true); }
TEST(RandomMachines, HoldResumeAndAbortOnMoreMachines) { check_rate_changes(32, 480, true, true); }

// Programs of those soaks that failed once, each alone (seed, index in its sequence):
// - 61/1689: resumed at rest, every plan reached axis 0's acceleration limit 1.2-1.4e-8 above it
//   (a jerk stage of 20 us on a 20 ms box), beyond the sweep's slack of 1e-8; the last resort then
//   restored the hold's plan, braked to a standstill, and the tool never started again.
// - 56/634: a new rate while a resume was still being retried kept the hold's braking (its plan
//   restored from before the resume): braked to rest, and never started again.
// - 47/393: not the plan; the third differences of positions rounded to doubles at a 0.25 ms
//   period (difference_noise).
// - 34/1723 (and 33/1222, 37/207, 38/858, 36/1423): held, the check also summed the legs after
//   the hold's stop (the resume's start), which cancelled the braking: 2x an axis' acceleration.
// - 32/295: a block braking to rest at its end planned its cruise at the lowest speed passing,
//   6e-15 mm/s: the hold never arrived and the abort after it never came to rest.
// - 33/962, 38/1102: the start after a hold's stop began inside the wider kernel of the step before the
//   stop; the check refused every such start and an unchecked plan started at speed 0 for ever.
// - 35/350: a hold braked a dense junction to 5e-6 mm/s and the next (dense) block kept that crawl.
// - 32/878, 37/363: a junction step of almost no speed change has a second stage of 1e-17 s; its
//   jerks of 1e21 cancelled with rounding errors of 1e5, the check refused the resume, and an
//   unchecked plan jumped 10 um at rest.
// - 41/404: at rest after a rate change, every plan reached axis 1's acceleration limit within
//   1.4e-9 of it (383.2225850 on 383.2225845), beyond the check's slack of 1e-9: every plan was
//   refused, and the unchecked one left a block its legs did not cover (a 1.5 mm jump).
// - 35/1070: stayed at rest for good under an attempted fix of 41/404 (kept as a guard).
// - 32/381: a hold braked a block to rest at its very end by a ramp (hold_end); the block stayed
//   in front with no length left, and the resume spun for ever on a start at speed 0.
TEST(RandomMachines, HoldResumeRegressions) {
    const std::pair<std::uint64_t, int> programs[] = {{34, 1723}, {33, 1222}, {37, 207}, {38, 858}, {36, 1423},
                                                      {33, 962}, {38, 1102}, {35, 350}, {32, 878}, {37, 363},
                                                      {41, 404}, {35, 1070}, {47, 393}, {56, 634}, {61, 1689}, {32, 295},
                                                      {32, 381}};
    for (const auto& [seed, index] : programs) {
        SCOPED_TRACE("seed " + std::to_string(seed) + ", program " + std::to_string(index));
        check_rate_changes(seed, 0, true, true, index);
    }
}
