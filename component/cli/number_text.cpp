#include "number_text.hpp"

#include <charconv>
#include <cstdio>

namespace firtp::cli {

void append_number(std::string& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value == 0.0 ? 0.0 : value);
    out.append(buffer, result.ptr);
}

std::string number_text(double value) {
    std::string out;
    append_number(out, value);
    return out;
}

std::string fixed_text(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value == 0.0 ? 0.0 : value);
    return buffer;
}

}  // namespace firtp::cli
