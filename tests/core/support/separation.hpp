// Random programs are measured by following the path from junction to junction; that is well
// defined when segments that are not neighbours stay apart by more than the tool can stray.
#pragma once

#include <firtp/types.hpp>

#include <algorithm>
#include <vector>

namespace firtp::test {

// Closest distance between segments [a0, a1] and [b0, b1] (clamped closest points, Ericson 5.1.9).
inline double segment_distance(const AxisVector& a0, const AxisVector& a1, const AxisVector& b0, const AxisVector& b1) {
    const AxisVector d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    double s = 0.0, t = 0.0;
    if (a <= 1e-300 && e <= 1e-300) return r.norm();
    if (a <= 1e-300) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e <= 1e-300) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denom = a * e - b * b;
            s = denom > 1e-300 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) t = 0.0, s = std::clamp(-c / a, 0.0, 1.0);
            else if (t > 1.0) t = 1.0, s = std::clamp((b - c) / a, 0.0, 1.0);
        }
    }
    return (a0 + d1 * s - (b0 + d2 * t)).norm();
}

// True when every two segments of the polyline through `points` that are not neighbours stay at
// least `gap` apart (3 tolerances plus a servo step, say).
inline bool well_separated(const std::vector<AxisVector>& points, double gap) {
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        for (std::size_t k = i + 2; k + 1 < points.size(); ++k)
            if (segment_distance(points[i], points[i + 1], points[k], points[k + 1]) < gap) return false;
    return true;
}

}  // namespace firtp::test
