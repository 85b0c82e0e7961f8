#include "python_comment.hpp"

#include <array>
#include <cctype>

namespace firtp::gcode {
namespace {

// Whether `text` starts with `word`, in any case.
bool starts_with_word(std::string_view text, std::string_view word) {
    if (text.size() < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[i])) != word[i]) return false;
    return true;
}

}  // namespace

std::optional<LineProblem> python_comment_problem(std::string_view line) {
    static constexpr std::array<std::string_view, 3> words{"py,", "pyrun,", "pyreload"};
    for (std::size_t open = line.find('('); open != std::string_view::npos; open = line.find('(', open + 1)) {
        std::size_t i = open + 1;
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        for (const std::string_view word : words)
            if (starts_with_word(line.substr(i), word))
                return LineProblem{static_cast<int>(i) + 1,
                                   "a Python comment (py,...), (pyrun,...) or (pyreload): firtp does not run Python "
                                   "from a program"};
    }
    return std::nullopt;
}

}  // namespace firtp::gcode
