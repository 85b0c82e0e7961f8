#include <firtp/overlap.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

namespace {

double half_turn_sine(double beta) { return std::sin(0.5 * beta); }

// Tk for an error target of `ratio` = eps / (F s); +inf when the corner is straight.
double ratio(double epsilon, double F, double beta) {
    const double s = half_turn_sine(beta);
    return s > 0.0 ? epsilon / (F * s) : std::numeric_limits<double>::infinity();
}

}  // namespace

double corner_error_eq13(double F, double beta, double Tk, double T1) {
    return F * Tk * Tk * half_turn_sine(beta) / (4.0 * T1);
}

double overlap_eq13(double epsilon, double F, double beta, double T1) {
    return std::clamp(std::sqrt(4.0 * T1 * ratio(epsilon, F, beta)), 0.0, T1);
}

double overlap_eq14(double epsilon, double F, double beta, double T1, double T2) {
    const double r = ratio(epsilon, F, beta);
    const double short_branch = std::cbrt(24.0 * T1 * T2 * r);
    if (short_branch <= 2.0 * T2) return short_branch;
    return std::min(T1 + T2, T2 + std::sqrt(4.0 * T1 * r - T2 * T2 / 3.0));
}

double corner_error_symmetric(const FirChain& chain, double F, double beta, double Tk) {
    return 2.0 * F * half_turn_sine(beta) * chain.position(0.5 * Tk);
}

double overlap_symmetric(const FirChain& chain, double epsilon, double F, double beta) {
    const double td = chain.delay();
    if (corner_error_symmetric(chain, F, beta, td) <= epsilon) return td;
    double lo = 0.0, hi = td;  // R is increasing: bisect 2 F s R(Tk / 2) = eps
    for (int i = 0; i < 200 && hi - lo > 1e-15 * td; ++i) {
        const double mid = 0.5 * (lo + hi);
        (corner_error_symmetric(chain, F, beta, mid) <= epsilon ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace firtp
