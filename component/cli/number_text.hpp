// Numbers as text that reads back to the same double (shortest round-trip form).
#pragma once

#include <string>

namespace firtp::cli {

void append_number(std::string& out, double value);  // -0 is written as 0
std::string number_text(double value);

// Fixed-point with `decimals` digits, for people (summary, plot titles).
std::string fixed_text(double value, int decimals);

}  // namespace firtp::cli
