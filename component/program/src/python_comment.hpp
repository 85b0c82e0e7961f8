// LinuxCNC's interpreter hands (py,...), (pyrun,...) and (pyreload) comments to its embedded
// Python. Its plugin crashes on them: a null dereference in PyBytes_AsString when the text is not
// UTF-8, and a read past a heap buffer while it reports a Python syntax error (LinuxCNC 2.9, both
// found by fuzz.gcode). firtp does not run Python from a program: such a line is refused, with
// its place, before it executes.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace firtp::gcode {

// The problem with `line` (what, and the 1-based column of the comment's word), or none.
struct LineProblem {
    int column = 0;
    std::string what;
};
std::optional<LineProblem> python_comment_problem(std::string_view line);

}  // namespace firtp::gcode
