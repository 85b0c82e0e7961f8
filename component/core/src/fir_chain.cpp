#include <firtp/fir_chain.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace firtp {

namespace {

long double binomial(int n, int k) {
    long double b = 1.0L;
    for (int i = 1; i <= k; ++i) b = b * static_cast<long double>(n - k + i) / static_cast<long double>(i);
    return b;
}

}  // namespace

// R(t) = 1 / (T1...Tn (n+1)!) * sum over subsets J of {1..n} of (-1)^|J| (t - T_J)_+^(n+1),
// T_J the sum of the subset's times. On each piece between consecutive subset sums it is one
// polynomial; its coefficients about the piece's start are computed in long double.
FirChain::FirChain(const FilterTimes& filters) : filters_(filters) {
    if (const char* why = validate(filters); *why) throw std::invalid_argument(why);
    const int n = filters.stages;
    degree_ = n + 1;
    delay_ = filters.delay();

    const int subsets = 1 << n;
    std::array<long double, max_pieces> sum{};
    std::array<int, max_pieces> sign{};
    for (int j = 0; j < subsets; ++j) {
        sign[j] = 1;
        for (int i = 0; i < n; ++i)
            if (j & (1 << i)) {
                sum[j] += filters.T[i];
                sign[j] = -sign[j];
            }
    }

    std::array<long double, max_pieces> sorted = sum;
    std::sort(sorted.begin(), sorted.begin() + subsets);
    const long double merge = 1e-12L * delay_;
    int m = 0;  // distinct knots below Td
    for (int j = 0; j < subsets; ++j)
        if ((m == 0 || sorted[j] - knots_[m - 1] > merge) && sorted[j] < delay_ - merge)
            knots_[m++] = static_cast<double>(sorted[j]);
    pieces_ = m;
    knots_[m] = delay_;

    long double scale = 1.0L;
    for (int i = 0; i < n; ++i) scale *= filters.T[i];
    for (int k = 2; k <= degree_; ++k) scale *= k;

    for (int p = 0; p < pieces_; ++p) {
        const long double start = knots_[p];
        for (int c = 0; c <= degree_; ++c) {
            long double acc = 0.0L;
            for (int j = 0; j < subsets; ++j) {
                if (sum[j] > start + merge) continue;
                acc += sign[j] * std::pow(start - sum[j], static_cast<long double>(degree_ - c));
            }
            coeff_[p][c] = static_cast<double>(binomial(degree_, c) * acc / scale);
        }
    }
}

StepSample FirChain::step(double t) const {
    if (t <= 0.0) return {};
    if (t >= delay_) return {t - 0.5 * delay_, 1.0, 0.0, 0.0};
    const int p = static_cast<int>(std::upper_bound(knots_.begin() + 1, knots_.begin() + pieces_, t) -
                                   knots_.begin()) - 1;
    const double h = t - knots_[p];
    const auto& c = coeff_[p];
    StepSample s;
    for (int k = degree_; k >= 0; --k) {
        s.jerk = s.jerk * h + s.acceleration;
        s.acceleration = s.acceleration * h + s.velocity;
        s.velocity = s.velocity * h + s.position;
        s.position = s.position * h + c[k];
    }
    s.acceleration *= 2.0;
    s.jerk *= 6.0;
    return s;
}

double FirChain::position(double t) const {
    if (t <= 0.0) return 0.0;
    if (t >= delay_) return t - 0.5 * delay_;
    const int p = static_cast<int>(std::upper_bound(knots_.begin() + 1, knots_.begin() + pieces_, t) -
                                   knots_.begin()) - 1;
    const double h = t - knots_[p];
    double r = 0.0;
    for (int k = degree_; k >= 0; --k) r = r * h + coeff_[p][k];
    return r;
}

StepSample FirChain::pulse(double t, double tv) const {
    const StepSample a = step(t);
    const StepSample b = step(t - tv);
    return {(a.position - b.position) / tv, (a.velocity - b.velocity) / tv,
            (a.acceleration - b.acceleration) / tv, (a.jerk - b.jerk) / tv};
}

}  // namespace firtp
