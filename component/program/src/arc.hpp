// Arc geometry for G2/G3: the centre (I J K or R), the swept angle, points along the arc and how
// many chords approximate it. Internal to the G-code reader; lengths in mm, angles in radians.
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

// A geometric problem with the arc as programmed; the reader adds file, line and column.
class ArcError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// LinuxCNC's interpreter tolerances (interp_internal.hh), in mm for the program's units.
struct ArcTolerances {
    double min_radius = 0.00127;        // RADIUS_TOLERANCE: shorter radii are zero; also R's reach
    double radius_difference = 0.0;     // CENTER_ARC_RADIUS_TOLERANCE: 2 * 0.01 * sqrt 2 mm, 2 * 0.001 * sqrt 2 in
    double relative_difference = 0.001; // SPIRAL_RELATIVE_TOLERANCE
};
ArcTolerances arc_tolerances(double mm_per_unit);

// Centre of the arc of radius |radius| from start to end (R < 0: the arc longer than half a turn),
// as LinuxCNC's arc_data_r finds it. Throws ArcError when start equals end or |radius| is too small.
Eigen::Vector2d centre_from_radius(const Eigen::Vector2d& start, const Eigen::Vector2d& end, double radius,
                                   bool clockwise, double reach_tolerance);

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
