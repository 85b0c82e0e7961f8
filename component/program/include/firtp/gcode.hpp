// G-code reader for the LinuxCNC (RS274NGC) dialect, the subset firtp plans so far:
// G0 G1 G2 G3 with X Y Z A B C U V W, I J K R P (arcs), F (G94 units/min, the only feed mode),
// G17/G18/G19, G20/G21, G90/G91, G90.1/G91.1, G61/G61.1 (exact stop), G64 [P tol] [Q tol],
// N words, ( ) and ; comments, M2/M30, a '%' line. Anything else (G93, G95, G33, G38, canned
// cycles, ...) is an error that names file:line:column and what is wrong; nothing is returned then.
//
// Axes: A B C are rotary, in degrees (G20/G21 do not scale them); U V W are linear. Axis words
// beyond machine.limits.axes are errors.
//
// Feeds, as LinuxCNC defines them: F applies to the X Y Z length when any of X Y Z moves, else to
// the U V W length, else (A B C alone) F is degrees/min along the A B C length. The move lasts
// length / F, lengthened until every axis keeps its MAX_VELOCITY (|delta_a| / duration) and,
// unless only A B C move, the speed along that length keeps [TRAJ]MAX_LINEAR_VELOCITY. G0 takes
// the shortest duration those limits allow. Since the planner times a block as
// |delta over all nine axes| / block.feed, block.feed = |delta_9| / duration.
//
// Arcs (G2 clockwise, G3 counter-clockwise): G17 turns in X Y about Z, G18 in Z X about Y (LinuxCNC's
// order: G3 is counter-clockwise seen from +Y), G19 in Y Z about X. The centre is I J K (G18: K I,
// G19: J K): offsets from the start (G91.1, the default) or the centre itself (G90.1, both words
// needed); or R, the radius (R < 0: the arc longer than half a turn; no full circles). End = start
// with I J K is a full circle; P n (1..10000, not with G64 P on the same line) makes n turns. The
// normal axis and A B C U V W move linearly with the angle (helix). Tolerances are LinuxCNC's
// (interp_internal.hh): a radius under 0.00127 mm is zero; the start and end radii may differ by
// at most 0.0283 mm in G21 (0.00283 in in G20) and at most 0.1 % (the radius then changes linearly
// along the arc, a spiral); R must reach the end within 0.00127 mm.
// Each arc becomes equal-angle chord blocks with sagitta r (1 - cos(dtheta / 2)) at most
// machine.arc_chord_tolerance, at least four a full turn. All chords of an arc share one speed
// along the X Y Z helix (duration of a chord = its share of the helix length / speed); the speed
// is F, capped by the axis limits on every chord and [TRAJ]MAX_LINEAR_VELOCITY, and by the FIR
// chain's shrinking of a circle, about v^2 * sum(T_i^2) / (24 R): v <= sqrt(24 R tol / sum(T_i^2))
// with R the smaller end radius, T_i = machine.filter_times() (no cap when those are not known or tol is infinite). Chords
// inside an arc blend with the arc's tolerance (in G61/G61.1 with machine.default_tolerance, which
// the cap then uses); the last chord ends as the arc does. Every chord carries the arc's line.
//
// G64 Q (LinuxCNC's naive-CAM merging) is accepted and ignored: firtp plans every segment.
//
// The program is kept whole in memory: more than machine.max_program_blocks blocks (chords
// included) is an error at the line that goes beyond, before its blocks are made.
#pragma once

#include <firtp/machine.hpp>
#include <firtp/types.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace firtp {

class GcodeError : public std::runtime_error {
public:
    GcodeError(std::string file, int line, int column, const std::string& message);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    int column() const { return column_; }

private:
    std::string file_;
    int line_;
    int column_;
};

struct Program {
    std::string file;
    AxisVector start = AxisVector::Zero();  // machine position before the first block
    std::vector<Block> blocks;              // machine units (mm, deg), feed in units/s, line = source line
};

// G64 without P uses machine.default_tolerance; G64 P0 means no tolerance (+inf, full overlap).
Program parse_gcode(std::string_view text, const std::string& file_name, const MachineConfig& machine,
                    const AxisVector& start = AxisVector::Zero());
Program read_gcode(const std::filesystem::path& path, const MachineConfig& machine,
                   const AxisVector& start = AxisVector::Zero());

}  // namespace firtp
