// A number in firtp.so's loadrt words (`firtp run`/`serve` loading it, firtp-lcm-bridge logging how
// LinuxCNC loaded it): the shortest text that reads back as the same double, so the module, and a
// replay of it, get exactly the planner's numbers.
#pragma once

#include <charconv>
#include <string>

namespace firtp {

inline std::string loadrt_number(double value) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

}  // namespace firtp
