#include <firtp/dense_legs.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

std::optional<double> dense_leg_flip(const DenseLegs& legs, double n) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    // b <= n: a = b, the step b (u' - u): b^2 max_k |u'_k - u_k| / C_k <= min(L, L').
    double box_du = 0.0;
    for (int k = 0; k < legs.axes; ++k) {
        if (!std::isfinite(legs.cap[k])) continue;
        if (!(legs.cap[k] > 0.0)) return std::nullopt;
        box_du = std::max(box_du, std::abs(legs.u_next[k] - legs.u[k]) / legs.cap[k]);
    }
    const double below = box_du > 0.0 ? std::sqrt(std::min(legs.length, legs.next_length) / box_du) : infinity;
    // b > n: a = n, the step e - b d per axis (e = n u'_k, d = u_k). Leg before: h(b) = |e - b d| b
    // <= R = L C_k; leg after: |e - b d| <= Q = (L' / n) C_k, an interval [z - Q/|d|, z + Q/|d|]
    // around z = e / d (no bound at n = 0: that leg never ends).
    double up = infinity, low = 0.0;
    for (int k = 0; k < legs.axes; ++k) {
        if (!std::isfinite(legs.cap[k])) continue;
        const double d = legs.u[k], e = n * legs.u_next[k], R = legs.length * legs.cap[k];
        const double Q = n > 0.0 ? legs.next_length / n * legs.cap[k] : infinity;
        if (d == 0.0) {
            if (e != 0.0) up = std::min(up, R / std::abs(e));
            if (std::abs(e) > Q) up = -infinity;  // no b passes
            continue;
        }
        const double ad = std::abs(d), z = e / d, se = std::copysign(1.0, d) * e;
        // Between 0 and z, h rises to e^2 / (4 |d|) at z / 2 and falls again: a hole of failing
        // speeds above n where that top passes R.
        if (z > 0.0) {
            const double top = std::max(n, 0.5 * z);
            if (top < z && std::abs(e - top * d) * top > R) return std::nullopt;
        }
        // The upper root of |d| b^2 - se b - R = 0, without cancellation.
        const double disc = std::sqrt(e * e + 4.0 * ad * R);
        up = std::min(up, se >= 0.0 ? (se + disc) / (2.0 * ad) : 2.0 * R / (disc - se));
        if (std::isfinite(Q)) up = std::min(up, z + Q / ad), low = std::max(low, z - Q / ad);
    }
    const bool some_above = up > n && low < up;  // speeds above n that pass
    if (below >= n) {
        if (!some_above) return n;
        if (low > n) return std::nullopt;  // a gap of failing speeds just above n
        return up;
    }
    if (some_above) return std::nullopt;
    return below;
}

}  // namespace firtp
