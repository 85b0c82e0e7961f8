// Module parameters arrive as text (RTAPI has no double parameters): a number parameter must be a
// whole finite number, since strtod alone would read "0.1x" as 0.1 and "abc" as 0.
#pragma once

#include <cmath>
#include <cstdlib>
#include <optional>

namespace firtp {

// The whole text as a finite number; nothing for "", "abc", "0.1x", "nan", "inf".
inline std::optional<double> module_number(const char* text) {
    if (text == nullptr || *text == '\0') return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(value)) return std::nullopt;
    return value;
}

}  // namespace firtp
