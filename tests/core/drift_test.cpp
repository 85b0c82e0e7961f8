// No drift: after 10^7 servo ticks of motion the output at rest equals the command exactly.
#include "support/reference.hpp"

#include <firtp/interpolator.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <random>

using namespace firtp;

TEST(Drift, TenMillionTicksEndExactlyWhereCommanded) {
    PlannerParameters parameters;
    parameters.filters = test::chain_of({0.0371, 0.0133, 0.0049});  // not multiples of the period
    parameters.period = 0.001;
    const FirChain chain(parameters.filters);
    Interpolator interpolator(chain, parameters.period, 64, AxisVector::Zero());
    Planner planner(parameters, chain, AxisVector::Zero());

    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coordinate(-500.0, 500.0);
    AxisState state;
    std::int64_t blocks = 0, exact_stops_checked = 0;
    AxisVector target = AxisVector::Zero();
    while (interpolator.now_tick() < 10'000'000) {
        if (interpolator.free() > 0) {
            Block b;
            for (int a = 0; a < 3; ++a) b.target[a] = coordinate(rng) + 1e-7 * static_cast<double>(rng() % 1000);
            b.feed = 50.0 + static_cast<double>(rng() % 400);
            b.tolerance = 0.01;
            b.termination = blocks % 50 == 49 ? Termination::exact_stop : Termination::blend;
            b.line = ++blocks;
            ASSERT_EQ(planner.add(b, interpolator), Result::ok);
            target = b.target;
        }
        interpolator.tick(state);
        if (interpolator.idle()) {  // at rest between bursts: exactly on the last command
            ASSERT_EQ(state.position, target);
            ++exact_stops_checked;
        }
    }
    while (!interpolator.idle()) interpolator.tick(state);
    interpolator.tick(state);
    EXPECT_GE(interpolator.now_tick(), 10'000'000);
    EXPECT_EQ(state.position, target);
    EXPECT_EQ(state.velocity, AxisVector::Zero());
    EXPECT_GT(blocks, 1000);
}
