// Filter times tuned to structural modes (Eq. 8-10): zeros on the modes, the smallest delay among
// every assignment and k, the limits kept; residual vibration and the robust bands checked against
// a time-domain simulation of the mode driven by the chain's acceleration.
#include <firtp/fir_chain.hpp>
#include <firtp/mode_tuning.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace firtp {
namespace {

constexpr double pi = std::numbers::pi;

FilterTimes chain_of(std::vector<double> times) {
    std::sort(times.begin(), times.end(), std::greater<>());
    FilterTimes f;
    f.stages = static_cast<int>(times.size());
    for (std::size_t i = 0; i < times.size(); ++i) f.T[i] = times[i];
    return f;
}

// The mode x'' + 2 zeta w x' + w^2 x = -a(t), a = the chain's response to a unit velocity step
// (its impulse response), integrated with RK4 at 10 us; the residual amplitude once the response is
// over, as a share of what an unfiltered step (an impulse: x' jumps by -1) leaves, 1 / w_d.
double simulated_residual(const FilterTimes& filters, double f, double zeta) {
    const FirChain chain(filters);
    const double w = 2.0 * pi * f, wd = w * std::sqrt(1.0 - zeta * zeta);
    const double dt = 1e-5;
    const auto steps = static_cast<long>(std::ceil(chain.delay() / dt));
    const double h = chain.delay() / static_cast<double>(steps);
    // One stage's acceleration jumps at 0 and Td, on step boundaries: each step sees its own side.
    const double inside = 1e-9 * h;
    const auto accel = [&](double t) { return chain.step(t).acceleration; };
    double x = 0.0, v = 0.0;
    for (long k = 0; k < steps; ++k) {
        const double t = static_cast<double>(k) * h;
        const auto fx = [&](double tt, double xx, double vv) { return -accel(tt) - 2.0 * zeta * w * vv - w * w * xx; };
        const double k1x = v, k1v = fx(t + inside, x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = fx(t + 0.5 * h, x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = fx(t + 0.5 * h, x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = fx(t + h - inside, x + h * k3x, v + h * k3v);
        x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    }
    const double amplitude = std::hypot(x, (v + zeta * w * x) / wd);
    return amplitude * wd;
}

TEST(ModeTuning, ResidualVibrationFormulaMatchesSimulation) {
    for (const double zeta : {0.0, 0.02, 0.1}) {
        for (const FilterTimes& f : {chain_of({0.1}), chain_of({0.148, 0.089}), chain_of({0.06, 0.05, 0.02})}) {
            for (const double hz : {3.0, 6.8, 11.4, 17.0}) {
                const double formula = residual_vibration(f, hz, zeta);
                EXPECT_NEAR(simulated_residual(f, hz, zeta), formula, 1e-6 + 1e-4 * formula)
                    << "zeta " << zeta << " f " << hz << " stages " << f.stages;
            }
        }
    }
    // Undamped: the residual is the chain's magnitude (Eq. 9).
    const FilterTimes f = chain_of({0.148, 0.089});
    for (const double hz : {1.0, 5.0, 9.3}) EXPECT_NEAR(residual_vibration(f, hz, 0.0), chain_magnitude(f, hz), 1e-12);
}

// The paper's diamond (Section 4): modes 6.8 Hz and 11.4 Hz, v/a = 60 ms, no jerk limit.
TEST(ModeTuning, PaperDiamondModesSitOnZeros) {
    ModeTuning tuning;
    tuning.modes = {{6.8, 0.02, 1}, {11.4, 0.03, 0}};
    const std::array<double, 2> bounds{0.06, 0.0};
    const TunedFilters tuned = tune_filters(bounds, 2, tuning);
    ASSERT_EQ(tuned.filters.stages, 2);
    EXPECT_NEAR(tuned.filters.T[0], 1.0 / 6.8, 1e-15);   // 147.06 ms (the paper rounds to 148)
    EXPECT_NEAR(tuned.filters.T[1], 1.0 / 11.4, 1e-15);  // 87.72 ms (89)
    EXPECT_EQ(tuned.stages[0].mode, 0);
    EXPECT_EQ(tuned.stages[1].mode, 1);
    EXPECT_EQ(tuned.stages[0].k, 1);
    EXPECT_LT(chain_magnitude(tuned.filters, 6.8), 1e-14);
    EXPECT_LT(chain_magnitude(tuned.filters, 11.4), 1e-14);
    // Lightly damped: what is left is about zeta / (1 + ...) of one stage times the other stage's.
    EXPECT_LT(residual_vibration(tuned.filters, 6.8, 0.02), 0.01);
    EXPECT_LT(residual_vibration(tuned.filters, 11.4, 0.03), 0.005);
}

// Raising stage 1 to the next k / f would cost more than giving the mode to stage 2.
TEST(ModeTuning, ModeGoesToTheStageWhereItCostsLeast) {
    ModeTuning tuning;
    tuning.modes = {{40.0}};
    const std::array<double, 2> bounds{0.06, 0.05};  // built-in machine: v/a, a/j
    const TunedFilters tuned = tune_filters(bounds, 2, tuning);
    EXPECT_DOUBLE_EQ(tuned.filters.T[0], 0.06);        // left at v/a
    EXPECT_DOUBLE_EQ(tuned.filters.T[1], 2.0 / 40.0);  // a/j = 50 ms is already 2 / 40 Hz
    EXPECT_EQ(tuned.stages[1].mode, 0);
    EXPECT_EQ(tuned.stages[1].k, 2);
    EXPECT_EQ(tuned.stages[0].mode, -1);
}

// Brute force over every assignment and k = 1..12: no feasible chain has a smaller Td.
double brute_force_td(const std::vector<double>& bounds_in, const std::vector<double>& zeros, int stages) {
    const int n = std::max(stages, static_cast<int>(zeros.size()));
    std::vector<double> bounds(bounds_in.begin(), bounds_in.end());
    bounds.resize(static_cast<std::size_t>(n), 0.0);
    std::sort(bounds.begin(), bounds.end(), std::greater<>());
    double best = std::numeric_limits<double>::infinity();
    std::vector<int> k(zeros.size(), 1);
    const int free_stages = n - static_cast<int>(zeros.size());
    for (;;) {
        std::vector<double> times;
        for (std::size_t i = 0; i < zeros.size(); ++i) times.push_back(k[i] / zeros[i]);
        // Free stages: try every choice of bounds for them (they take their bound exactly).
        std::vector<int> pick(static_cast<std::size_t>(free_stages), 0);
        const std::function<void(int)> place = [&](int s) {
            if (s == free_stages) {
                std::vector<double> all = times;
                for (int p : pick) all.push_back(bounds[static_cast<std::size_t>(p)]);
                std::sort(all.begin(), all.end(), std::greater<>());
                bool ok = true;
                double td = 0.0;
                for (int r = 0; r < n; ++r) {
                    ok = ok && all[static_cast<std::size_t>(r)] > 0.0 &&
                         all[static_cast<std::size_t>(r)] >= bounds[static_cast<std::size_t>(r)] * (1 - 1e-12);
                    td += all[static_cast<std::size_t>(r)];
                }
                if (ok) best = std::min(best, td);
                return;
            }
            for (int p = 0; p < n; ++p) {
                pick[static_cast<std::size_t>(s)] = p;
                place(s + 1);
            }
        };
        place(0);
        std::size_t i = 0;
        while (i < k.size() && ++k[i] > 12) k[i++] = 1;  // bounds <= 0.15 s, f <= 60 Hz: k <= 10
        if (i == k.size()) break;
    }
    return best;
}

TEST(ModeTuning, DelayIsTheSmallestOfEveryAssignmentAndLimitsHold) {
    std::mt19937 rng(6);
    std::uniform_real_distribution<double> bound(0.005, 0.15), hz(3.0, 60.0);
    for (int trial = 0; trial < 60; ++trial) {
        const int modes = 1 + trial % 3;
        const int stages = std::min(4, modes + trial % 2);
        std::vector<double> bounds{bound(rng), trial % 5 == 0 ? 0.0 : bound(rng)};
        if (stages > 2 && trial % 3 == 0) bounds.push_back(bound(rng) / 3.0);
        ModeTuning tuning;
        std::vector<double> zeros;
        for (int m = 0; m < modes; ++m) {
            tuning.modes.push_back({hz(rng), 0.02, -1});
            zeros.push_back(tuning.modes.back().frequency_hz);
        }
        const double expected = brute_force_td(bounds, zeros, stages);
        if (!std::isfinite(expected)) {
            EXPECT_THROW(tune_filters(bounds, stages, tuning), std::invalid_argument);
            continue;
        }
        const TunedFilters tuned = tune_filters(bounds, stages, tuning);
        EXPECT_NEAR(tuned.filters.delay(), expected, 1e-12) << "trial " << trial;
        EXPECT_STREQ(validate(tuned.filters), "");
        // Limits: the i-th largest time at least the i-th largest bound.
        std::vector<double> sorted = bounds;
        sorted.resize(static_cast<std::size_t>(tuned.filters.stages), 0.0);
        std::sort(sorted.begin(), sorted.end(), std::greater<>());
        for (int i = 0; i < tuned.filters.stages; ++i)
            EXPECT_GE(tuned.filters.T[static_cast<std::size_t>(i)], sorted[static_cast<std::size_t>(i)]);
        // Every mode on a zero.
        for (const StructuralMode& m : tuning.modes) EXPECT_LT(chain_magnitude(tuned.filters, m.frequency_hz), 1e-12);
    }
}

TEST(ModeTuning, RobustOptionsPlaceTwoStagesPerMode) {
    ModeTuning tuning;
    tuning.modes = {{6.8, 0.02, 1}, {11.4, 0.03, 0}};
    const std::array<double, 2> bounds{0.06, 0.0};

    tuning.robust = RobustTuning::double_stage;
    const TunedFilters twice = tune_filters(bounds, 2, tuning);
    ASSERT_EQ(twice.filters.stages, 4);
    EXPECT_NEAR(twice.filters.delay(), 2.0 / 6.8 + 2.0 / 11.4, 1e-12);
    for (const StructuralMode& m : tuning.modes) {
        int on_mode = 0;
        for (int i = 0; i < 4; ++i) {
            const double x = twice.filters.T[static_cast<std::size_t>(i)] * m.frequency_hz;
            on_mode += std::abs(x - std::round(x)) < 1e-12 ? 1 : 0;
        }
        EXPECT_EQ(on_mode, 2) << m.frequency_hz;  // a double zero
    }

    tuning.robust = RobustTuning::straddle;
    tuning.spread = 0.15;
    const TunedFilters pair = tune_filters(bounds, 2, tuning);
    ASSERT_EQ(pair.filters.stages, 4);
    for (const StructuralMode& m : tuning.modes) {
        EXPECT_LT(chain_magnitude(pair.filters, m.frequency_hz * 0.85), 1e-12);
        EXPECT_LT(chain_magnitude(pair.filters, m.frequency_hz * 1.15), 1e-12);
    }

    tuning.modes.push_back({20.0});
    EXPECT_THROW(tune_filters(bounds, 2, tuning), std::invalid_argument);  // 6 stages
    tuning.robust = RobustTuning::none;
    tuning.modes.push_back({30.0});
    tuning.modes.push_back({40.0});
    EXPECT_THROW(tune_filters(bounds, 2, tuning), std::invalid_argument);  // 5 modes
}

TEST(ModeTuning, SameModeOnTwoAxesCountsOnce) {
    const std::vector<StructuralMode> modes{{10.0, 0.05, 0}, {10.0, 0.01, 1}, {12.0, 0.02, 2}};
    const std::vector<StructuralMode> distinct = distinct_modes(modes);
    ASSERT_EQ(distinct.size(), 2u);
    EXPECT_EQ(distinct[0].damping, 0.01);
    EXPECT_EQ(distinct[0].axis, -1);
    EXPECT_THROW(distinct_modes(std::vector<StructuralMode>{{-1.0}}), std::invalid_argument);
    EXPECT_THROW(distinct_modes(std::vector<StructuralMode>{{5.0, 1.0}}), std::invalid_argument);
}

// The reason tune_filters refuses, "" when it tunes.
std::string refusal(std::vector<double> bounds, int stages, std::vector<StructuralMode> modes,
                    RobustTuning robust = RobustTuning::none) {
    ModeTuning tuning;
    tuning.modes = std::move(modes);
    tuning.robust = robust;
    tuning.spread = robust == RobustTuning::straddle ? 0.2 : 0.0;
    try {
        tune_filters(bounds, stages, tuning);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

// Inputs the INI reader refuses before tuning, given to the tuner directly: it refuses them itself
// (k = L f beyond int was an undefined float-to-int conversion), whatever the magnitudes.
TEST(ModeTuning, StagesBeyondAMillionModePeriodsAreRefused) {
    ModeTuning tuning;
    tuning.modes = {{10.0}};
    const TunedFilters most = tune_filters(std::vector<double>{1e5}, 1, tuning);  // k = 10^6 exactly
    EXPECT_EQ(most.stages[0].k, 1000000);
    EXPECT_EQ(refusal({1e5 + 0.2}, 1, {{10.0}}),
              "10 Hz: a filter stage of at least 100000 s would span more than a million periods of this mode");
    EXPECT_EQ(refusal({1e300}, 1, {{10.0}}),
              "10 Hz: a filter stage of at least 1e+300 s would span more than a million periods of this mode");
    EXPECT_EQ(refusal({0.06}, 1, {{1e300}}),
              "1e+300 Hz: a filter stage of at least 0.06 s would span more than a million periods of this mode");
    EXPECT_EQ(refusal({std::numeric_limits<double>::max(), 0.01}, 2, {{1e-3}, {1e300}}),
              "0.001 Hz: a filter stage of at least 1.79769e+308 s would span more than a million periods of this mode");
    EXPECT_EQ(refusal({0.06}, 1, {{std::numeric_limits<double>::denorm_min()}}),
              "4.94066e-324 Hz: one period of this mode (1 / f) is not a finite time");
    EXPECT_EQ(refusal({0.06}, 1, {{1.5e308}}, RobustTuning::straddle),
              "1.5e+308 Hz: the straddled zero f (1 + spread) is not finite");
    EXPECT_EQ(refusal({1e308}, 2, {{1e-308}}), "the filter delay T1 + ... + Tn is not finite");
    // A stage without a mode can take the huge bound: tuned, k small (the window check refuses it later).
    const TunedFilters spare = tune_filters(std::vector<double>{1e300, 0.01}, 2, tuning);
    EXPECT_EQ(spare.filters.T[0], 1e300);
    EXPECT_EQ(spare.stages[1].k, 1);
    // A missing stage is still named as such, not blamed on the modes.
    EXPECT_EQ(refusal({1e300, 0.0, 0.0}, 3, {{10.0}}), "T3 is neither given nor derivable from the axis limits or a mode");
    // Tiny and enormous modes that stay within a million periods still tune.
    EXPECT_EQ(refusal({0.06}, 1, {{1e-300}}), "");
    EXPECT_EQ(refusal({1e-300}, 1, {{1e300}}), "");
}

// The plain Hz list ([FIRTP]MODES = 6.8 11.4) through the old entry point.
TEST(ModeTuning, PlainFrequencyListKeepsWorking) {
    MachineLimits limits;
    limits.axes = 2;
    limits.axis[0] = limits.axis[1] = AxisLimits{300.0, 5000.0, 0.0};
    const std::vector<double> hz{6.8, 11.4};
    const FilterTimes f = filter_times_from_limits(limits, 2, {}, hz);
    EXPECT_NEAR(f.T[0], 1.0 / 6.8, 1e-15);
    EXPECT_NEAR(f.T[1], 1.0 / 11.4, 1e-15);
    // Given times are lower bounds: T1 = 148 ms pushes 11.4 Hz to k = 2 (175 ms), 6.8 Hz stays k = 1.
    const std::vector<double> given{0.148};
    const FilterTimes g = filter_times_from_limits(limits, 2, given, hz);
    EXPECT_NEAR(g.T[0], 2.0 / 11.4, 1e-15);
    EXPECT_NEAR(g.T[1], 1.0 / 6.8, 1e-15);
    EXPECT_THROW(filter_times_from_limits(limits, 2, {}, {}), std::invalid_argument);  // T2: no jerk limit
}

// The robust bands that examples/VIBRATION.md quotes (5 % of the unfiltered step, damping 0.02):
// found by the band search, then confirmed by simulating the mode just inside and just outside.
TEST(ModeTuning, RobustBandsReproducedBySimulation) {
    struct Case {
        RobustTuning robust;
        double spread, low, high;
        bool open_above;
    };
    const StructuralMode mode{10.0, 0.02, -1};
    const double auto_spread = straddle_spread(mode.damping);
    EXPECT_NEAR(auto_spread, 0.255, 1e-9);  // on the search grid of 0.005
    const Case cases[] = {
        {RobustTuning::none, 0.0, -0.0468, 0.0525, false},
        {RobustTuning::double_stage, 0.0, -0.2001, 1.0, true},
        {RobustTuning::straddle, 0.15, -0.2470, 1.0, true},
        {RobustTuning::straddle, auto_spread, -0.3184, 1.0, true},
    };
    for (const Case& c : cases) {
        const FilterTimes stages = mode_stages(mode, c.robust, c.spread);
        const FrequencyBand band = vibration_band(stages, nullptr, mode.frequency_hz, mode.damping);
        ASSERT_FALSE(band.empty);
        EXPECT_NEAR(band.low, c.low, 5e-4);
        EXPECT_NEAR(band.high, c.high, 5e-4);
        EXPECT_EQ(band.open_above, c.open_above);
        const auto simulated = [&](double e) {
            return simulated_residual(stages, mode.frequency_hz * (1.0 + e), mode.damping);
        };
        EXPECT_LE(simulated(band.low + 0.002), 0.05);
        EXPECT_GT(simulated(band.low - 0.002), 0.05);
        if (!band.open_above) {
            EXPECT_LE(simulated(band.high - 0.002), 0.05);
            EXPECT_GT(simulated(band.high + 0.002), 0.05);
        }
    }
}

// The diamond machine's band against the untuned chain (T from the limits: 60 ms, 50 ms): the
// literal "5 % of the untuned case", simulated at the edges too.
TEST(ModeTuning, BandAgainstTheUntunedChain) {
    const FilterTimes untuned = chain_of({0.06, 0.05});
    const FilterTimes tuned = chain_of({1.0 / 6.8, 1.0 / 11.4});
    const FrequencyBand y = vibration_band(tuned, &untuned, 6.8, 0.02);
    ASSERT_FALSE(y.empty);
    EXPECT_NEAR(y.low, -0.055, 0.001);
    EXPECT_NEAR(y.high, 0.068, 0.001);
    const auto ratio = [&](double f, double zeta) {
        return simulated_residual(tuned, f, zeta) / simulated_residual(untuned, f, zeta);
    };
    EXPECT_LT(ratio(6.8, 0.02), 0.02);
    EXPECT_LE(ratio(6.8 * (1.0 + y.low + 0.002), 0.02), 0.05);
    EXPECT_GT(ratio(6.8 * (1.0 + y.low - 0.002), 0.02), 0.05);
    EXPECT_LE(ratio(6.8 * (1.0 + y.high - 0.002), 0.02), 0.05);
    EXPECT_GT(ratio(6.8 * (1.0 + y.high + 0.002), 0.02), 0.05);
}

}  // namespace
}  // namespace firtp
