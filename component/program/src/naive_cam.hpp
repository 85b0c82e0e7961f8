// LinuxCNC's naive-CAM detector (G64 P p Q q), which its task applies to the canon's moves before
// any planner sees them (emccanon.cc): in G64, straight feeds are collected while every point
// collected lies within q of the one segment from where the collection began to the newest point,
// at most 101 points and none turning A B C U V W; the collection reaches the planner as that one
// segment. An arc in the XY plane whose chord passes within q of it joins as two straight moves
// through its middle. Q defaults to P (the interpreter's rule); Q0 turns it off. The reader does
// the same (canon_recorder.cpp), so `firtp plan` plans the moves LinuxCNC hands firtp_tp.
#pragma once

#include <firtp/types.hpp>

#include <Eigen/Core>

#include <optional>
#include <span>

namespace firtp::gcode {

struct ChainPoint {
    AxisVector at;  // machine units
    int line = 0;
};

constexpr std::size_t max_chain_points = 101;

// Whether `target` may join the collection `chain` that began at `start` (machine units, q in mm).
bool extends_chain(std::span<const ChainPoint> chain, const AxisVector& start, const AxisVector& target, double q);

// The farthest of `chain`'s points but its last from the segment `start` to its last (X Y Z).
double chain_deviation(std::span<const ChainPoint> chain, const AxisVector& start);

// A one-turn arc in the XY plane from `start` to `end` about `centre` (counter-clockwise when
// `ccw`) whose chord deviation r (1 - cos(sweep / 2)) is below q: its middle, at the middle angle
// on the start's radius, every other axis half way. None otherwise.
std::optional<AxisVector> naive_arc_middle(const AxisVector& start, const AxisVector& end, const Eigen::Vector2d& centre,
                                           bool ccw, double q);

}  // namespace firtp::gcode
