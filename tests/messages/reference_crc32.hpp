// CRC-32 (IEEE 802.3) bit by bit from its definition (reflected polynomial 0xEDB88320, initial
// value and final xor 0xFFFFFFFF), independent of Boost: what the message tests and fuzz_lcm check
// the seal against.
#pragma once

#include <cstddef>
#include <cstdint>

namespace firtp::test {

inline std::uint32_t reference_crc32(const std::uint8_t* data, std::size_t size) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
}

}  // namespace firtp::test
