#include "python_comment.hpp"

#include <cctype>
#include <cstdio>

namespace firtp::gcode {
namespace {

// Length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlongs, no surrogates,
// nothing above U+10FFFF), 0 if there is none.
std::size_t utf8_sequence(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
    const unsigned b0 = byte(i);
    if (b0 < 0x80) return 1;
    std::size_t n = 0;
    unsigned lo = 0x80, hi = 0xBF;  // the range of the second byte
    if (b0 >= 0xC2 && b0 <= 0xDF) n = 2;
    else if (b0 >= 0xE0 && b0 <= 0xEF) n = 3, lo = b0 == 0xE0 ? 0xA0 : 0x80, hi = b0 == 0xED ? 0x9F : 0xBF;
    else if (b0 >= 0xF0 && b0 <= 0xF4) n = 4, lo = b0 == 0xF0 ? 0x90 : 0x80, hi = b0 == 0xF4 ? 0x8F : 0xBF;
    else return 0;
    if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    return n;
}

bool starts_python(std::string_view comment) {  // after '(' and any blanks: "py" in any case
    return comment.size() >= 2 && std::tolower(static_cast<unsigned char>(comment[0])) == 'p' &&
           std::tolower(static_cast<unsigned char>(comment[1])) == 'y';
}

}  // namespace

std::optional<LineProblem> python_comment_problem(std::string_view line) {
    for (std::size_t open = line.find('('); open != std::string_view::npos; open = line.find('(', open + 1)) {
        std::size_t i = open + 1;
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        if (!starts_python(line.substr(i))) continue;
        const std::size_t close = line.find(')', i);
        const std::size_t end = close == std::string_view::npos ? line.size() : close;
        for (std::size_t k = i; k < end;) {
            const std::size_t n = utf8_sequence(line, k);
            if (n == 0) {
                char what[96];
                std::snprintf(what, sizeof what, "a Python comment (py...) must be UTF-8 text: byte 0x%02X is not",
                              static_cast<unsigned>(static_cast<unsigned char>(line[k])));
                return LineProblem{static_cast<int>(k) + 1, what};
            }
            k += n;
        }
    }
    return std::nullopt;
}

}  // namespace firtp::gcode
