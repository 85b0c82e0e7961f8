// Analytic sampled trajectories for the measure tests, built without the planner.
#pragma once

#include <firtp/types.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace firtp::test {

inline constexpr double sample_period = 1e-3;  // the measure tests' period, s

inline AxisVector axes(double x, double y = 0.0, double z = 0.0) {
    AxisVector v = AxisVector::Zero();
    v << x, y, z, 0, 0, 0, 0, 0, 0;
    return v;
}

// Samples at times 0, period, 2 period, ...
inline std::vector<AxisState> timed(const std::vector<AxisVector>& positions, double period) {
    std::vector<AxisState> out(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        out[i].time = static_cast<double>(i) * period;
        out[i].position = positions[i];
    }
    return out;
}

// Appends `steps` points from a towards b, without b itself.
inline void append_line(std::vector<AxisVector>& out, const AxisVector& a, const AxisVector& b, int steps) {
    for (int s = 0; s < steps; ++s) out.push_back(a + (b - a) * (static_cast<double>(s) / steps));
}

inline void append_dwell(std::vector<AxisVector>& out, const AxisVector& p, int count) {
    for (int s = 0; s < count; ++s) out.push_back(p);
}

// Angle by which the path turns at `corner`.
inline double turn_angle(const AxisVector& before, const AxisVector& corner, const AxisVector& after) {
    const double c = (corner - before).normalized().dot((after - corner).normalized());
    return std::acos(std::clamp(c, -1.0, 1.0));
}

// A circular fillet of radius r tangent to both legs: its closest approach to the corner, and its
// largest distance from the legs (at the arc's middle).
inline double fillet_corner_distance(double r, double turn) { return r * (1.0 / std::cos(turn / 2.0) - 1.0); }
inline double fillet_contour_distance(double r, double turn) { return r * (1.0 - std::cos(turn / 2.0)); }

// The polyline with every interior point j rounded by an arc of radius radii[j-1]; line pieces get
// `line_steps` samples, arcs `arc_steps` (even: the arc's middle is a sample).
inline std::vector<AxisVector> filleted(const std::vector<AxisVector>& points, const std::vector<double>& radii,
                                        int line_steps, int arc_steps) {
    std::vector<AxisVector> out;
    AxisVector from = points.front();
    for (std::size_t j = 1; j + 1 < points.size(); ++j) {
        const AxisVector u = (points[j] - points[j - 1]).normalized();
        const AxisVector w = (points[j + 1] - points[j]).normalized();
        const double turn = turn_angle(points[j - 1], points[j], points[j + 1]);
        const double r = radii[j - 1];
        const AxisVector normal = (w - w.dot(u) * u).normalized();
        const AxisVector entry = points[j] - r * std::tan(turn / 2.0) * u;
        const AxisVector center = entry + r * normal;
        append_line(out, from, entry, line_steps);
        for (int s = 0; s < arc_steps; ++s) {
            const double phi = turn * s / arc_steps;
            out.push_back(center + r * (std::sin(phi) * u - std::cos(phi) * normal));
        }
        from = center + r * (std::sin(turn) * u - std::cos(turn) * normal);
    }
    append_line(out, from, points.back(), line_steps);
    out.push_back(points.back());
    return out;
}

}  // namespace firtp::test
