// Helpers for the G-code reader tests: parse text, build axis vectors, walk the blocks.
#pragma once

#include <firtp/gcode.hpp>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace firtp::test {

// LinuxCNC refuses a file that ends with neither M2/M30 nor '%': snippets get an M2.
inline std::string ended(std::string_view text) { return std::string(text) + "\nM2\n"; }

inline Program parse(std::string_view text, const MachineConfig& machine = default_machine(),
                     const AxisVector& start = AxisVector::Zero()) {
    return parse_gcode(ended(text), "t.ngc", machine, start);
}

// "no error" or the GcodeError's message.
inline std::string parse_error(std::string_view text, const MachineConfig& machine = default_machine()) {
    try {
        parse_gcode(ended(text), "t.ngc", machine);
    } catch (const GcodeError& e) {
        return e.what();
    }
    return "no error";
}

// at({{'X', 1}, {'A', 90}}): a position with the named axes set, the others zero.
inline AxisVector at(std::initializer_list<std::pair<char, double>> values) {
    AxisVector v = AxisVector::Zero();
    for (const auto& [letter, value] : values)
        for (std::size_t a = 0; a < axis_letters.size(); ++a)
            if (axis_letters[a] == letter) v[static_cast<Eigen::Index>(a)] = value;
    return v;
}

// The program's start, then every block's target.
inline std::vector<AxisVector> points(const Program& p) {
    std::vector<AxisVector> out{p.start};
    for (const Block& b : p.blocks) out.push_back(b.target);
    return out;
}

// How long each block takes as the planner times it: |delta over all nine axes| / feed.
inline std::vector<double> durations(const Program& p) {
    std::vector<double> out;
    AxisVector from = p.start;
    for (const Block& b : p.blocks) {
        out.push_back((b.target - from).norm() / b.feed);
        from = b.target;
    }
    return out;
}

inline double total(const std::vector<double>& values) {
    double sum = 0.0;
    for (const double v : values) sum += v;
    return sum;
}

// A machine with all nine axes, each at 300 units/s (A B C: deg/s), 5000 units/s^2, 100000 units/s^3.
inline MachineConfig nine_axis_machine() {
    MachineConfig m = default_machine();
    m.limits.axes = 9;
    for (auto& axis : m.limits.axis) axis = AxisLimits{300.0, 5000.0, 100000.0};
    return m;
}

}  // namespace firtp::test
