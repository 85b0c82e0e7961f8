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

ArcTolerances arc_tolerances(double mm_per_unit) {
    ArcTolerances t;
    t.radius_difference = 2.0 * (mm_per_unit == 1.0 ? 0.01 : 0.001) * std::numbers::sqrt2 * mm_per_unit;
    return t;
}

Eigen::Vector2d centre_from_radius(const Eigen::Vector2d& start, const Eigen::Vector2d& end, double radius,
                                   bool clockwise, double reach_tolerance) {
    if ((end - start).norm() <= zero_length)
        throw ArcError("an R arc cannot be a full circle: the end point equals the start point (use I J K)");
    const double r = std::abs(radius);
    const Eigen::Vector2d mid = (start + end) / 2.0;
    double half = (end - mid).norm();
    if (half - r > reach_tolerance)
        throw ArcError(cat("radius ", mm(r), " mm is too small to reach the end point (half the chord is ", mm(half),
                           " mm)"));
    if (half / r > 1.0 - 1e-12) half = r;  // a half circle, within rounding
    const bool right = clockwise == (radius > 0.0);
    const double theta = std::atan2(end.y() - start.y(), end.x() - start.x()) +
                         (right ? -std::numbers::pi / 2 : std::numbers::pi / 2);
    const double offset = r * std::cos(std::asin(half / r));
    return mid + offset * Eigen::Vector2d(std::cos(theta), std::sin(theta));
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
