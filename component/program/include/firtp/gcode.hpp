// G-code reader: LinuxCNC 2.9's own RS274NGC interpreter (librs274, package linuxcnc-uspace),
// driven through its canonical-machining interface (canon.hh) as LinuxCNC's standalone `rs274`
// drives it. Everything LinuxCNC accepts reads: parameters, expressions, O-word subroutines and
// loops, canned cycles, G28/G30, G43 tool length, G54..G59.3 and G92 offsets, G20 inches, G41/G42
// cutter compensation, G93/G95 feed modes. What the interpreter refuses is a GcodeError
// "file:line: <LinuxCNC's message>" and no program is returned.
//
// The canon calls become firtp blocks (rs274_canon.cpp, canon_recorder.cpp):
// - STRAIGHT_TRAVERSE (G0) at the axes' limits; STRAIGHT_FEED at F, with LinuxCNC's feed rules:
//   F applies to the X Y Z length when any of X Y Z moves, else to U V W, else (A B C alone) F is
//   degrees/min. The move lasts length / F, lengthened until every axis keeps its MAX_VELOCITY and,
//   unless only A B C move, the speed keeps [TRAJ]MAX_LINEAR_VELOCITY. Since the planner times a
//   block as |delta over all nine axes| / block.feed, block.feed = |delta_9| / duration.
// - ARC_FEED as equal-angle chords with sagitta at most machine.arc_chord_tolerance, at least four
//   a full turn, all at one speed along the X Y Z helix: F, capped by the axis limits on every chord
//   and, on the paper's fixed chain, by the FIR chain's shrinking of a circle (arc_speed_limit).
//   Chords inside an arc blend with the arc's tolerance (in G61/G61.1 with
//   machine.default_tolerance); the last chord ends as the arc does. Every chord carries the arc's line.
// - Coordinates: the canon reports program units relative to the work offsets; the recorder
//   applies G92, the XY rotation, G5x and the tool length offset as LinuxCNC's emccanon does, and
//   G20 inches become mm (A B C stay degrees).
// - SET_MOTION_CONTROL_MODE: G61/G61.1 stop exactly; G64 P p blends within p; G64 without P (and
//   G64 P0, which the canon cannot tell apart) uses machine.default_tolerance.
// - G64 Q q (q = p when only P is given; Q0 turns it off): straight feeds within q of one segment
//   become that segment, as LinuxCNC's task merges them before its planner sees them
//   (naive_cam.hpp; Program::joined counts the moves that joined a longer block).
// - Spindle, tool, coolant, pause, dwell and end are ProgramEvents between blocks (program_event.hpp).
//
// Files the interpreter needs: the INI (machine.ini_file, else none), its parameter file
// ([RS274NGC]PARAMETER_FILE, copied so the program cannot change the user's) and tool table
// ([EMCIO]TOOL_TABLE), else an empty parameter file and tools T1..T999 of zero length, all in a
// temporary directory removed afterwards.
// One program is read at a time in a process (the interpreter is one global object).
//
// More than machine.max_program_blocks blocks (chords included) is an error at the line that goes
// beyond. read_gcode keeps the program whole in memory; a ProgramSink receives it as it is made.
#pragma once

#include <firtp/machine.hpp>
#include <firtp/program_event.hpp>
#include <firtp/types.hpp>

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace firtp {

// what() is "file:line: message", or "file:line:column: message" when the column is known (> 0).
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

// Straight feeds G64 Q joined into longer blocks (naive_cam.hpp).
struct JoinedMoves {
    std::size_t moves = 0;  // feeds that joined a longer block
    double farthest = 0.0;  // mm: the farthest a joined feed's end lies from its block
};

struct Program {
    std::string file;
    AxisVector start = AxisVector::Zero();  // machine position before the first block
    std::vector<Block> blocks;              // machine units (mm, deg), feed in units/s, line = source line
    std::vector<ProgramEvent> events;       // in program order, before_block not decreasing
    JoinedMoves joined;                     // G64 Q
};

// Receives a program as the interpreter makes it, in program order: each block once it is final
// (an event that waits still turns the block before it into an exact stop), each event after the
// blocks it follows. On a GcodeError what it received is not a program: discard it.
class ProgramSink {
public:
    virtual ~ProgramSink() = default;
    virtual void block(const Block& block) = 0;
    virtual void event(const ProgramEvent& event) = 0;
    // At the end: the straight feeds G64 Q joined into longer blocks.
    virtual void joined(const JoinedMoves&) {}
};

// `text` is read as the file `file_name` (errors name it); subroutines are looked up as for a file
// in the current directory.
Program parse_gcode(std::string_view text, const std::string& file_name, const MachineConfig& machine,
                    const AxisVector& start = AxisVector::Zero());
Program read_gcode(const std::filesystem::path& path, const MachineConfig& machine,
                   const AxisVector& start = AxisVector::Zero());
// The same, handing blocks and events to `sink` instead of keeping them (program.start is `start`).
void read_gcode(const std::filesystem::path& path, const MachineConfig& machine, const AxisVector& start,
                ProgramSink& sink);

}  // namespace firtp
