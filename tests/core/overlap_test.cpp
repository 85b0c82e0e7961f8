// Eq. 13/14 and the any-chain solution against the corner error measured on a simulated
// running-sum FIR chain at 10 us, over a grid of angles, tolerances and filter times.
#include "support/reference.hpp"

#include <firtp/corner.hpp>
#include <firtp/overlap.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace firtp;
using firtp::test::chain_of;
using firtp::test::xyz;

namespace {

constexpr double deg = std::numbers::pi / 180.0;
const double angles_deg[] = {5, 30, 45, 90, 120, 143, 180};

// Closest approach to the corner of two long blocks at feed F, turning by beta, overlapped by Tk.
double measured_corner_error(const FilterTimes& f, double F, double beta, double Tk, double dt = 1e-5) {
    const double td = f.delay(), tv = td + 0.05, length = F * tv;
    const AxisVector in = xyz(length, 0), out = xyz(length * std::cos(beta), length * std::sin(beta));
    const std::vector<test::Pulse> pulses{{in, 0.0, tv}, {out, tv + td - Tk, tv}};
    const int steps = static_cast<int>((2 * tv + 2 * td) / dt);
    const auto p = test::simulate_discrete_fir(f, AxisVector::Zero(), pulses, dt, steps);
    double closest = 1e300;
    for (const AxisVector& q : p) closest = std::min(closest, (q - in).norm());
    return closest;
}

}  // namespace

TEST(Overlap, Eq13AndEq14AgreeWithTheAnyChainSolution) {
    for (double F : {50.0, 250.0})
        for (double eps : {0.005, 0.05, 0.5, 2.0})
            for (double a : angles_deg) {
                const double beta = a * deg;
                const FirChain one(chain_of({0.02}));
                EXPECT_NEAR(overlap_symmetric(one, eps, F, beta), overlap_eq13(eps, F, beta, 0.02), 1e-12);
                for (auto [T1, T2] : {std::pair{0.148, 0.089}, std::pair{0.06, 0.01}, std::pair{0.03, 0.03}}) {
                    const FirChain two(chain_of({T1, T2}));
                    EXPECT_NEAR(overlap_symmetric(two, eps, F, beta), overlap_eq14(eps, F, beta, T1, T2), 1e-12)
                        << "F " << F << " eps " << eps << " beta " << a << " T " << T1 << "," << T2;
                }
            }
}

TEST(Overlap, Eq13MatchesFigure4) {
    const double s45 = std::sin(45 * deg);
    EXPECT_NEAR(corner_error_eq13(50.0, 90 * deg, 0.020, 0.020), 50.0 * 0.020 * s45 / 4, 1e-15);
    EXPECT_NEAR(corner_error_eq13(50.0, 90 * deg, 0.020, 0.020), 0.1768, 5e-5);
    EXPECT_NEAR(corner_error_eq13(50.0, 90 * deg, 0.010, 0.020), 0.0442, 5e-5);
}

TEST(Overlap, Eq14BranchesMeetAtTwoT2AndGiveTheSectionFourOverlap) {
    const double T1 = 0.148, T2 = 0.089, F = 250.0, beta = 90 * deg;
    EXPECT_NEAR(overlap_eq14(0.5, F, beta, T1, T2), 0.09634, 5e-6);  // paper notes: 96.34 ms
    // Error at Tk = 2 T2 from either branch's formula is the same.
    const double s = std::sin(beta / 2), Tk = 2 * T2;
    const double short_branch = F * s * Tk * Tk * Tk / (24 * T1 * T2);
    const double long_branch = F * s / (4 * T1) * ((Tk - T2) * (Tk - T2) + T2 * T2 / 3);
    EXPECT_NEAR(short_branch, long_branch, 1e-12);
}

TEST(Overlap, ClosedFormsMatchTheMeasuredCornerErrorOfASimulatedChain) {
    const FilterTimes chains[] = {chain_of({0.02}), chain_of({0.148, 0.089}), chain_of({0.06, 0.01}),
                                  chain_of({0.05, 0.03, 0.01}), chain_of({0.04, 0.03, 0.02, 0.01})};
    for (const FilterTimes& f : chains) {
        const FirChain chain(f);
        for (double eps : {0.05, 0.5, 2.0})
            for (double a : angles_deg) {
                const double F = 250.0, beta = a * deg;
                const double Tk = f.stages == 1   ? overlap_eq13(eps, F, beta, f.T[0])
                                  : f.stages == 2 ? overlap_eq14(eps, F, beta, f.T[0], f.T[1])
                                                  : overlap_symmetric(chain, eps, F, beta);
                const double measured = measured_corner_error(f, F, beta, Tk);
                if (Tk < f.delay() - 1e-12) {
                    EXPECT_NEAR(measured, eps, 2e-4 * eps) << f.stages << " stages, eps " << eps << ", beta " << a;
                } else {
                    EXPECT_LE(measured, eps * (1 + 2e-4)) << f.stages << " stages, full overlap, beta " << a;
                }
            }
    }
}

TEST(Overlap, SolverKeepsTheSampledErrorWithinToleranceForUnequalFeedsAndShortBlocks) {
    const FilterTimes f = chain_of({0.06, 0.02});
    const FirChain chain(f);
    struct Case { double f_in, f_out, l_in, l_out, beta_deg; };
    for (const Case c : {Case{100, 250, 30, 30, 90}, Case{250, 40, 30, 5, 60}, Case{200, 200, 2, 2, 120},
                         Case{300, 300, 0.5, 20, 170}, Case{50, 300, 10, 0.3, 45}}) {
        const double beta = c.beta_deg * deg;
        const AxisVector in = xyz(c.l_in, 0), out = xyz(c.l_out * std::cos(beta), c.l_out * std::sin(beta));
        const CornerModel model{&chain, in, c.l_in / c.f_in, out, c.l_out / c.f_out};
        const double eps = 0.05, dt = 1e-5;
        const double Tk_max = std::min({f.delay(), model.in_tv + f.delay(), 0.5 * (model.out_tv + f.delay())});
        const double Tk = solve_overlap(model, eps, ToleranceMeaning::corner_point, 1e-3, Tk_max);
        const std::vector<test::Pulse> pulses{{in, 0.0, model.in_tv}, {out, model.in_tv + f.delay() - Tk, model.out_tv}};
        const int steps = static_cast<int>((model.in_tv + model.out_tv + 2 * f.delay()) / dt);
        const auto p = test::simulate_discrete_fir(f, AxisVector::Zero(), pulses, dt, steps);
        double closest = 1e300;
        for (const AxisVector& q : p) closest = std::min(closest, (q - in).norm());
        EXPECT_LE(closest, eps) << "case f_in " << c.f_in << " f_out " << c.f_out;
        if (Tk < Tk_max) {
            EXPECT_GT(closest, 0.9 * eps) << "needlessly conservative, f_in " << c.f_in;
        }
        EXPECT_NEAR(model.corner_error(Tk), closest, 1e-3 * eps + 1e-6);
    }
}

TEST(Overlap, ContourMeaningAllowsMoreOverlapAndBoundsTheDistanceToThePath) {
    const FilterTimes f = chain_of({0.148, 0.089});
    const FirChain chain(f);
    const double F = 250, tv = 0.4, eps = 0.5;
    for (double a : {45.0, 90.0, 135.0}) {
        const double beta = a * deg;
        const AxisVector in = xyz(F * tv, 0), out = xyz(F * tv * std::cos(beta), F * tv * std::sin(beta));
        const CornerModel model{&chain, in, tv, out, tv};
        const double Tk_corner = solve_overlap(model, eps, ToleranceMeaning::corner_point, 1e-3, f.delay());
        const double Tk_contour = solve_overlap(model, eps, ToleranceMeaning::contour, 1e-3, f.delay());
        EXPECT_GT(Tk_contour, Tk_corner);
        EXPECT_LE(model.contour_error(Tk_contour), eps * (1 + 1e-9));
        // Symmetric case: contour error is the corner error times cos(beta / 2) (paper notes).
        EXPECT_NEAR(model.contour_error(Tk_corner), model.corner_error(Tk_corner) * std::cos(beta / 2), 1e-6);
    }
}
