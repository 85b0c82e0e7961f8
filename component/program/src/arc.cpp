#include "arc.hpp"

#include "move_speed.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace firtp::gcode {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

std::string mm(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", value);
    return text;
}

Eigen::Vector2d in_plane(const AxisVector& p, const ArcPlane& plane) { return {p[plane.first], p[plane.second]}; }

}  // namespace

ArcPlane arc_plane(int plane_code) {
    switch (plane_code) {
        case 180: return {2, 0, 1};
        case 190: return {1, 2, 0};
        default: return {0, 1, 2};
    }
}

Arc make_arc(const ArcPlane& plane, const AxisVector& start, const AxisVector& end, const Eigen::Vector2d& centre,
             bool clockwise, int turns, const ArcTolerances& tolerances) {
    Arc arc;
    arc.plane = plane;
    arc.start = start;
    arc.end = end;
    arc.centre = centre;
    const Eigen::Vector2d from = in_plane(start, plane) - centre, to = in_plane(end, plane) - centre;
    arc.start_radius = from.norm();
    arc.end_radius = to.norm();
    const std::string radii = cat(" (start ", mm(arc.start_radius), " mm, end ", mm(arc.end_radius), " mm)");
    if (arc.start_radius < tolerances.min_radius || arc.end_radius < tolerances.min_radius)
        throw ArcError(cat("zero-radius arc: the centre is on the start or the end point", radii));
    const double difference = std::abs(arc.start_radius - arc.end_radius);
    if (difference > tolerances.radius_difference ||
        difference > tolerances.relative_difference * std::max(arc.start_radius, arc.end_radius))
        throw ArcError(cat("radius to end of arc differs from radius to start", radii));

    arc.start_angle = std::atan2(from.y(), from.x());
    const double end_angle = std::atan2(to.y(), to.x());
    double angle = clockwise ? arc.start_angle - end_angle : end_angle - arc.start_angle;
    if ((to - from).norm() <= zero_length) angle = two_pi;  // end = start: a full turn
    else if (angle <= 0.0) angle += two_pi;
    angle += two_pi * (turns - 1);
    arc.sweep = clockwise ? -angle : angle;
    return arc;
}

double Arc::helix_length() const {
    const double planar = std::abs(sweep) * (start_radius + end_radius) / 2.0;
    return std::hypot(planar, end[plane.normal] - start[plane.normal]);
}

AxisVector Arc::point(double fraction) const {
    if (fraction >= 1.0) return end;
    AxisVector p = start + (end - start) * fraction;
    const double radius = start_radius + (end_radius - start_radius) * fraction;
    const double angle = start_angle + sweep * fraction;
    p[plane.first] = centre.x() + radius * std::cos(angle);
    p[plane.second] = centre.y() + radius * std::sin(angle);
    return p;
}

int chord_count(const Arc& arc, double chord_tolerance) {
    const double sweep = std::abs(arc.sweep);
    // sagitta = r (1 - cos(d / 2)) = 2 r sin^2(d / 4) <= tolerance
    const double ratio = chord_tolerance / (2.0 * std::max(arc.start_radius, arc.end_radius));
    const double by_sagitta = ratio >= 1.0 ? 1.0 : std::ceil(sweep / (4.0 * std::asin(std::sqrt(ratio))));
    const double by_turn = std::ceil(sweep / (std::numbers::pi / 2) - 1e-9);
    const double n = std::max({1.0, by_sagitta, by_turn});
    if (!(n <= max_arc_chords))
        throw ArcError(cat("the arc needs more than ", std::to_string(max_arc_chords),
                           " chords: raise [FIRTP]ARC_CHORD_TOLERANCE"));
    return static_cast<int>(n);
}

}  // namespace firtp::gcode
