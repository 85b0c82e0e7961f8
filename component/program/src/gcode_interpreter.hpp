// Runs G-code lines in LinuxCNC's order and turns their moves into blocks. Internal to the reader.
#pragma once

#include "gcode_words.hpp"

#include <firtp/machine.hpp>
#include <firtp/types.hpp>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace firtp::gcode {

struct Modal {
    int motion = -1;            // 0 (G0), 10 (G1), 20 (G2), 30 (G3) or -1 before the first
    int plane = 170;            // G17, G18, G19
    double scale = 1.0;         // mm per program unit (G21 / G20)
    bool incremental = false;   // G91
    bool arc_absolute = false;  // G90.1: I J K are the centre itself, not offsets from the start
    Termination termination = Termination::blend;
    double tolerance = 0.0;     // mm
    double feed = 0.0;          // mm/min, kept across G20/G21 as LinuxCNC does
    double angular_feed = 0.0;  // deg/min (F as written) for moves of A B C alone
};

class Interpreter {
public:
    Interpreter(const MachineConfig& machine, const AxisVector& start, std::vector<Block>& blocks);

    // Runs one line (F, plane, units, G61/G64, G90/G91, G90.1/G91.1, motion, M2); true when it
    // ends the program.
    bool run(const LineWords& w, const Where& at);

private:
    void check_word_use(const LineWords& w, const Where& at) const;
    void set_control_mode(const LineWords& w, const Where& at);
    AxisVector target_of(const LineWords& w) const;
    void line(const AxisVector& target, int column, const Where& at);
    void arc(const LineWords& w, const AxisVector& target, int column, const Where& at);
    Eigen::Vector2d arc_centre(const LineWords& w, const AxisVector& target, int column, const Where& at) const;
    int arc_turns(const LineWords& w, const Where& at) const;
    std::string too_many_blocks() const;
    void push(const AxisVector& target, double feed, Termination termination, double tolerance, MotionType type,
              int column, const Where& at);

    const MachineConfig& machine_;
    std::optional<FilterTimes> filters_;  // the paper's fixed chain, whose arcs need a feed cap
    AxisVector position_;
    std::vector<Block>& blocks_;
    Modal state_;
};

}  // namespace firtp::gcode
