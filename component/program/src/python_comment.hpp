// LinuxCNC's interpreter hands (py,...), (pyrun,...) and (pyreload) comments to its embedded
// Python, whose plugin dereferences a null pointer when the comment is not UTF-8 text (LinuxCNC
// 2.9: a segmentation fault in PyBytes_AsString). Such a line is refused before it executes.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace firtp::gcode {

// The problem with `line` (what, and the 1-based column of the first bad byte), or none.
struct LineProblem {
    int column = 0;
    std::string what;
};
std::optional<LineProblem> python_comment_problem(std::string_view line);

}  // namespace firtp::gcode
