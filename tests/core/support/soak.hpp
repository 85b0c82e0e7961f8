// Soak runs of the randomized suites: FIRTP_RANDOM_SEED shifts every seed, FIRTP_RANDOM_SCALE
// multiplies every count (a fraction too: .ci/run's sanitized pass runs half of each suite the
// plain build ran whole).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace firtp::test {

inline std::uint64_t random_seed_offset() {
    const char* v = std::getenv("FIRTP_RANDOM_SEED");
    return v ? std::strtoull(v, nullptr, 10) : 0;
}

inline int random_scaled(int count) {
    const char* v = std::getenv("FIRTP_RANDOM_SCALE");
    const double scale = v ? std::strtod(v, nullptr) : 1.0;
    return scale > 0.0 ? std::max(1, static_cast<int>(std::lround(count * scale))) : count;
}

}  // namespace firtp::test
