// What LinuxCNC's canonical-machining calls do to a firtp program: the canon's state (units,
// offsets, feed, motion mode, spindle, tool) and the blocks and events it makes. Internal to the
// reader; rs274_canon.cpp forwards the canon's C++ functions here. The interpreter must not see an
// exception: the first problem is kept (failed()) and later calls are ignored.
#pragma once

#include "naive_cam.hpp"

#include <firtp/gcode.hpp>
#include <firtp/machine.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace firtp::gcode {

// Where the interpreter is: its current file and line (for events and errors).
struct Place {
    std::string file;
    int line = 0;
};

class CanonRecorder {
public:
    // `where` asks the interpreter for its place; `start` is the machine position. Blocks and
    // events go to `sink` once final: the newest block (and the events after it) at the next
    // block or at finish().
    CanonRecorder(const MachineConfig& machine, const AxisVector& start, ProgramSink& sink,
                  std::function<Place()> where);

    // The end of the program: hands over what is held back.
    void finish();
    std::size_t blocks() const { return blocks_; }  // made so far
    std::size_t events() const { return events_; }

    // Program units (mm or inch): conversions in and out of the canon.
    void set_units_inch(bool inch) { scale_ = inch ? 25.4 : 1.0; }
    bool units_inch() const { return scale_ != 1.0; }
    // Offsets in program units at the time of the call (kept in mm). LinuxCNC's task applies a new
    // one once motion has finished.
    void set_g5x(const AxisVector& offset) { motion_waits(), g5x_ = to_mm(offset); }
    void set_g92(const AxisVector& offset) { motion_waits(), g92_ = to_mm(offset); }
    void set_tool_offset(const AxisVector& offset) { motion_waits(), tool_ = to_mm(offset); }
    void set_xy_rotation(double degrees) { motion_waits(), rotation_deg_ = degrees; }
    // The current position as the interpreter sees it: program units, offsets removed.
    AxisVector program_position() const;
    AxisVector tool_offset_program() const { return from_mm(tool_); }

    void set_feed_rate(double program_units_per_min);  // F (G93: the interpreter's rate for the move)
    double feed_rate_program() const { return feed_ / scale_; }
    void set_feed_per_revolution(bool per_rev) { end_chain(), per_rev_ = per_rev; }
    void set_exact_stop() { end_chain(), termination_ = Termination::exact_stop, tolerance_ = 0.0; }
    void set_blend(double program_tolerance);  // 0: machine.default_tolerance
    bool exact_stop() const { return termination_ == Termination::exact_stop; }
    double tolerance_program() const { return tolerance_ / scale_; }
    // G64 Q (naive_cam.hpp), program units; 0 collects nothing.
    void set_naive_cam(double program_tolerance) { naive_cam_ = program_tolerance * scale_; }
    double naive_cam_program() const { return naive_cam_ / scale_; }
    // Hands the straight feeds collected so far to the planner as one block (a canon call LinuxCNC
    // ends a collection at).
    void end_chain();
    // A canon call LinuxCNC's task executes only once motion has finished (an event that waits,
    // an operator message, an offset, an output now, ...): the block before ends in an exact stop
    // when motion follows. After the last block nothing is marked: firtp_tp sees the end of its
    // queue there, as at any program end.
    void motion_waits();

    void straight(bool rapid, int line, const AxisVector& program_target);
    // ARC_FEED: ends and centre in the plane's (first, second) axes, `normal_end` the helix axis'
    // end, `others` A B C U V W; rotation > 0 counter-clockwise, |rotation| turns.
    void arc(int line, int plane_code, double first_end, double second_end, double first_centre,
             double second_centre, int rotation, double normal_end, const AxisVector& program_target);

    void spindle_speed(double rpm);
    double spindle_rpm() const { return rpm_; }
    int spindle_direction() const { return direction_; }
    void spindle_start(bool clockwise);
    void spindle_stop();
    void event(EventKind kind, double value = 0.0);
    void select_tool(int tool) { selected_tool_ = tool; event(EventKind::tool_select, tool); }
    int selected_tool() const { return selected_tool_; }
    void change_tool(int tool) { tool_in_spindle_ = tool; event(EventKind::tool_change, tool); }
    int tool_in_spindle() const { return tool_in_spindle_; }
    bool flood() const { return flood_; }
    bool mist() const { return mist_; }
    void coolant(EventKind kind);

    // A canon call firtp cannot plan (probing, spindle-synchronised motion, ...).
    void refuse(const std::string& what);
    const std::optional<GcodeError>& failed() const { return error_; }

private:
    AxisVector to_mm(const AxisVector& program) const;    // linear axes scaled, A B C as they are
    AxisVector from_mm(const AxisVector& mm) const;
    AxisVector to_machine(const AxisVector& program) const;  // emccanon's rotate_and_offset
    void line_block(bool rapid, int line, const AxisVector& target);
    void feed_point(int line, const AxisVector& target);  // a straight feed, collected in G64 Q
    const AxisVector& last_point() const { return chain_.empty() ? position_ : chain_.back().at; }
    void push(const AxisVector& target, double feed, Termination termination, double tolerance, MotionType type,
              int line);
    double programmed_speed(bool linear) const;
    std::string too_many_blocks() const;  // mm/s or deg/s; 0 when none
    void fail(int line, const std::string& message);

    void release();  // the held block, then the events after it, to the sink

    const MachineConfig& machine_;
    ProgramSink& sink_;
    std::optional<Block> held_;              // the newest block: a waiting event may still end it
    bool wait_pending_ = false;              // motion waits after held_ (marked when a block follows)
    std::vector<ProgramEvent> held_events_;  // the events since it
    std::size_t blocks_ = 0, events_ = 0;
    std::function<Place()> where_;
    std::optional<FilterTimes> filters_;  // the paper's fixed chain, whose arcs need a feed cap
    AxisVector position_;                 // machine, mm and degrees
    double scale_ = 1.0;                  // mm per program unit
    AxisVector g5x_ = AxisVector::Zero(), g92_ = AxisVector::Zero(), tool_ = AxisVector::Zero();
    double rotation_deg_ = 0.0;
    double feed_ = 0.0;                   // mm/min (deg/min for A B C alone: F as written)
    double feed_written_ = 0.0;
    bool per_rev_ = false;
    Termination termination_ = Termination::blend;
    double tolerance_ = 0.0;              // mm
    double rpm_ = 0.0;
    double dwell_ = 0.0;                  // G4 since the last block: the next block's dwell
    int direction_ = 0;                   // 1 clockwise, -1 counter-clockwise, 0 stopped
    int selected_tool_ = 0, tool_in_spindle_ = 0;
    double naive_cam_ = 0.0;           // mm
    std::vector<ChainPoint> chain_;    // straight feeds collected since position_
    JoinedMoves joined_;
    bool flood_ = false, mist_ = false;
    std::optional<GcodeError> error_;
};

}  // namespace firtp::gcode
