// Joins pieces of text by appending; GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
#pragma once

#include <string>

namespace firtp {

template <class... Parts>
std::string cat(const Parts&... parts) {
    std::string s;
    ((s += parts), ...);
    return s;
}

}  // namespace firtp
