#include <firtp/mode_response.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace firtp {
namespace {

constexpr double rest_threshold = 1e-9;

using Matrix6 = Eigen::Matrix<double, 6, 6>;

// exp(m) by scaling and squaring with a Taylor series: the 6 x 6 matrices here have small norms
// after scaling, so 20 terms reach double precision.
Matrix6 exponential(const Matrix6& m) {
    const double norm = m.cwiseAbs().rowwise().sum().maxCoeff();
    int squarings = 0;
    if (norm > 0.5) squarings = static_cast<int>(std::ceil(std::log2(norm / 0.5)));
    const Matrix6 scaled = m / std::ldexp(1.0, squarings);
    Matrix6 term = Matrix6::Identity(), sum = Matrix6::Identity();
    for (int k = 1; k <= 20; ++k) {
        term = term * scaled / static_cast<double>(k);
        sum += term;
    }
    for (int i = 0; i < squarings; ++i) sum = sum * sum;
    return sum;
}

// One period of the oscillator z = (x, x'), z' = A z + b u, for u(s) = c0 + c1 s + c2 s^2 + c3 s^3:
// z(h) = phi z(0) + sum_m gamma_m c_m, gamma_m = int_0^h exp(A (h - s)) b s^m ds.
struct Discretisation {
    Eigen::Matrix2d phi;
    std::array<Eigen::Vector2d, 4> gamma;
};

Discretisation discretise(double w, double zeta, double h) {
    // [A, b e0^T; 0, N] with N the shift of (1, s, s^2/2, s^3/6): its exponential's top-right
    // block holds int exp(A (h - s)) b s^m / m! ds in column m.
    Matrix6 m = Matrix6::Zero();
    m(0, 1) = 1.0;
    m(1, 0) = -w * w;
    m(1, 1) = -2.0 * zeta * w;
    m(1, 2) = 1.0;
    m(2, 3) = 1.0;
    m(3, 4) = 1.0;
    m(4, 5) = 1.0;
    const Matrix6 e = exponential(m * h);
    Discretisation d;
    d.phi = e.topLeftCorner<2, 2>();
    const double factorial[4] = {1.0, 1.0, 2.0, 6.0};
    for (int c = 0; c < 4; ++c) d.gamma[c] = factorial[c] * e.block<2, 1>(0, 2 + c);
    return d;
}

bool at_rest(const AxisState& s) {
    return s.velocity.cwiseAbs().maxCoeff() <= rest_threshold && s.acceleration.cwiseAbs().maxCoeff() <= rest_threshold;
}

}  // namespace

ModeResponse simulate_mode(std::span<const AxisState> samples, int axis, double frequency_hz, double damping,
                           double period) {
    if (!(frequency_hz > 0.0 && damping >= 0.0 && damping < 1.0 && period > 0.0))
        throw std::invalid_argument("simulate_mode: frequency > 0, 0 <= damping < 1 and period > 0");
    ModeResponse r;
    if (samples.empty()) return r;
    const auto a_index = static_cast<Eigen::Index>(axis);
    const double w = 2.0 * std::numbers::pi * frequency_hz;
    const double sigma = damping * w, wd = w * std::sqrt(1.0 - damping * damping);
    const Discretisation d = discretise(w, damping, period);

    const auto amplitude = [&](const Eigen::Vector2d& z, double a, double j) {
        const double e = z[0] + (a - 2.0 * damping * j / w) / (w * w);
        const double e_rate = z[1] + j / (w * w);
        return std::hypot(e, (e_rate + sigma * e) / wd);
    };

    Eigen::Vector2d z = Eigen::Vector2d::Zero();
    r.deflection.reserve(samples.size());
    r.vibration.reserve(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const double a = samples[k].acceleration[a_index], j = samples[k].jerk[a_index];
        if (k > 0) {
            // Hermite cubic through (a, j) at both ends; the oscillator is driven by -a.
            const double a0 = samples[k - 1].acceleration[a_index], j0 = samples[k - 1].jerk[a_index];
            const double h = period;
            const double c0 = a0, c1 = j0;
            const double c2 = (3.0 * (a - a0) / h - 2.0 * j0 - j) / h;
            const double c3 = (2.0 * (a0 - a) / h + j0 + j) / (h * h);
            z = d.phi * z - (c0 * d.gamma[0] + c1 * d.gamma[1] + c2 * d.gamma[2] + c3 * d.gamma[3]);
        }
        const double vib = amplitude(z, a, j);
        r.deflection.push_back(z[0]);
        r.vibration.push_back(vib);
        const bool rest = at_rest(samples[k]);
        if (rest && k > 0 && !at_rest(samples[k - 1])) {
            r.stops.push_back({k, samples[k].time, vib});
            r.max_stop_residual = std::max(r.max_stop_residual, vib);
        }
        if (!rest) {
            r.max_moving_vibration = std::max(r.max_moving_vibration, vib);
            r.max_moving_deflection = std::max(r.max_moving_deflection, std::abs(z[0]));
        }
    }
    r.final_residual = r.vibration.back();
    return r;
}

std::vector<double> acceleration_spectrum(std::span<const AxisState> samples, int axis,
                                          std::span<const double> frequencies_hz) {
    std::vector<double> out;
    out.reserve(frequencies_hz.size());
    const auto a_index = static_cast<Eigen::Index>(axis);
    const double period = samples.size() > 1 ? samples[1].time - samples[0].time : 0.0;
    for (const double f : frequencies_hz) {
        // Rotating phasor, renormalised now and then against drift.
        const std::complex<double> step = std::polar(1.0, -2.0 * std::numbers::pi * f * period);
        std::complex<double> phasor = std::polar(1.0, samples.empty() ? 0.0 : -2.0 * std::numbers::pi * f * samples[0].time);
        std::complex<double> sum = 0.0;
        for (std::size_t k = 0; k < samples.size(); ++k) {
            sum += samples[k].acceleration[a_index] * phasor;
            phasor *= step;
            if (k % 256 == 255) phasor /= std::abs(phasor);
        }
        out.push_back(std::abs(sum) * period);
    }
    return out;
}

}  // namespace firtp
