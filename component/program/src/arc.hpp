// Arc geometry for ARC_FEED (G2/G3): the swept angle, points along the arc and how many chords
// approximate it. Internal to the G-code reader; lengths in mm, angles in radians.
#pragma once

#include <firtp/types.hpp>

#include <Eigen/Core>

#include <stdexcept>

namespace firtp::gcode {

// The two axes an arc turns in, counter-clockwise from `first` towards `second`, and the axis
// normal to them. G17: X Y (Z). G18: Z X (Y), LinuxCNC's order, so G3 is counter-clockwise seen
// from +Y. G19: Y Z (X).
struct ArcPlane {
    int first;
    int second;
    int normal;
};
ArcPlane arc_plane(int plane_code);  // 170, 180 or 190

// A geometric problem with the arc; the reader adds file and line.
class ArcError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Radius tolerances (LinuxCNC's interpreter has checked its own before the canon sees an arc).
struct ArcTolerances {
    double min_radius = 0.0;           // shorter radii are zero
    double radius_difference = 0.0;    // start and end radii may differ by this much (mm)
    double relative_difference = 0.0;  // and by this share of the larger
};

// A circular or (within the tolerance) spiral arc: the radius changes linearly with the angle and
// every axis other than the plane's two moves linearly with it (helix).
struct Arc {
    ArcPlane plane{0, 1, 2};
    AxisVector start = AxisVector::Zero();
    AxisVector end = AxisVector::Zero();
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    double start_radius = 0.0;
    double end_radius = 0.0;
    double start_angle = 0.0;  // of start - centre in the plane
    double sweep = 0.0;        // > 0 counter-clockwise; a full turn (end = start) is 2 pi, P n adds n - 1 turns

    double helix_length() const;              // X Y Z path: planar arc length with the normal axis' travel
    AxisVector point(double fraction) const;  // 0 start, 1 exactly `end`
};

// Throws ArcError for a zero radius or start and end radii that differ beyond the tolerances.
Arc make_arc(const ArcPlane& plane, const AxisVector& start, const AxisVector& end, const Eigen::Vector2d& centre,
             bool clockwise, int turns, const ArcTolerances& tolerances);

// Equal-angle chords whose sagitta r (1 - cos(dtheta / 2)) is at most chord_tolerance, at least
// four a full turn and at least one. Throws ArcError past max_arc_chords: a turn needs at most
// ~2,200 (1 m radius, 1 um chords) but P allows 10,000 turns; memory is bounded by
// MachineConfig::max_program_blocks, so this only catches absurd chord tolerances early.
constexpr int max_arc_chords = 1'000'000;
int chord_count(const Arc& arc, double chord_tolerance);

}  // namespace firtp::gcode
