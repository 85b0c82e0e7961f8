// No drift: after 10^7 servo ticks of motion the output at rest equals the command exactly, with
// the paper's fixed chain (times not multiples of the period) and smoothing at the limits.
#include "support/limits.hpp"
#include "support/reference.hpp"

#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <random>

using namespace firtp;

namespace {

void run_ten_million_ticks(const PlannerParameters& parameters) {
    Planner planner(parameters, AxisVector::Zero());
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coordinate(-500.0, 500.0);
    AxisState state;
    std::int64_t blocks = 0, exact_stops_checked = 0;
    AxisVector target = AxisVector::Zero();
    while (planner.ticks() < 10'000'000) {
        if (planner.free() > 0 && planner.depth() < 8) {
            Block b;
            for (int a = 0; a < 3; ++a) b.target[a] = coordinate(rng) + 1e-7 * static_cast<double>(rng() % 1000);
            b.feed = 50.0 + static_cast<double>(rng() % 400);
            b.tolerance = 0.01;
            b.termination = blocks % 50 == 49 ? Termination::exact_stop : Termination::blend;
            b.line = ++blocks;
            ASSERT_EQ(planner.add(b), Result::ok);
            target = b.target;
        }
        planner.tick(state);
        if (planner.idle()) {  // at rest between bursts: exactly on the last command
            ASSERT_EQ(state.position, target);
            ++exact_stops_checked;
        }
    }
    planner.finish();
    while (!planner.idle()) planner.tick(state);
    planner.tick(state);
    EXPECT_EQ(state.position, target);
    EXPECT_EQ(state.velocity, AxisVector::Zero());
    EXPECT_GT(blocks, 1000);
}

}  // namespace

TEST(Drift, TenMillionTicksEndExactlyWhereCommanded) {
    PlannerParameters parameters;
    parameters.fixed_chain = true;
    parameters.filters = test::chain_of({0.0371, 0.0133, 0.0049});  // not multiples of the period
    parameters.period = 0.001;
    run_ten_million_ticks(parameters);
}

TEST(Drift, TenMillionTicksAtTheLimitsEndExactlyWhereCommanded) {
    PlannerParameters parameters;
    parameters.limits = test::uniform_limits(400.0, 3700.0, 91000.0);  // jerk time 40.7 ms, not a multiple of the period
    parameters.period = 0.001;
    run_ten_million_ticks(parameters);
}
