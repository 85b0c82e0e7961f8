// LinuxCNC's feed rules for a move over up to nine axes (G94, units per minute), turned into the
// block feed the planner expects (Tv = |delta over all nine axes| / feed). Internal to the reader.
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

namespace firtp::gcode {

// Shorter moves (units or degrees) count as not moving; a move where no group moves is dropped,
// as LinuxCNC's canon drops empty moves.
constexpr double zero_length = 1e-9;

// Lengths of a move's axis groups, summed in a fixed order so that `all` equals `xyz` bit for bit
// when only X Y Z move.
struct MoveLengths {
    double xyz = 0.0;
    double abc = 0.0;  // degrees
    double uvw = 0.0;
    double all = 0.0;  // all nine, as the planner measures the block

    // The length F applies to: X Y Z if they move, else U V W, else A B C (degrees).
    double feed_length() const;
    // True unless only A B C move: [TRAJ]MAX_LINEAR_VELOCITY applies then.
    bool linear() const;
    bool moves() const { return xyz > zero_length || uvw > zero_length || abc > zero_length; }
};

MoveLengths move_lengths(const AxisVector& delta);

// Highest speed along a path of length `path` (traversed by the axis motion `delta`) that each
// axis' MAX_VELOCITY allows (|delta_a| / duration <= v_a), and [TRAJ]MAX_LINEAR_VELOCITY when
// `linear`. Infinite when nothing limits it.
double speed_cap(const AxisVector& delta, double path, bool linear, const MachineLimits& limits);

}  // namespace firtp::gcode
