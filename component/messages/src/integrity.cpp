// End-to-end integrity of firtp_lcm messages: the CRC-32 in their last field (block_t.lcm).
#include <firtp/messages.hpp>

#include <boost/crc.hpp>

#include <cinttypes>
#include <cstdio>

namespace firtp::messages {
namespace {

constexpr std::size_t fingerprint_size = 8;
constexpr std::size_t crc_size = 4;

std::uint32_t big_endian32(const std::uint8_t* p) {
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | std::uint32_t{p[3]};
}

// The first 8 bytes, big-endian (as many as there are).
std::uint64_t fingerprint_of(const void* data, std::size_t size) {
    std::uint64_t fingerprint = 0;
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < fingerprint_size && i < size; ++i) fingerprint = fingerprint << 8 | bytes[i];
    return fingerprint;
}

}  // namespace

std::uint32_t crc32(const void* data, std::size_t size) {
    boost::crc_32_type crc;
    crc.process_bytes(data, size);
    return crc.checksum();
}

bool intact(const void* data, std::size_t size) { return !integrity_problem(data, size); }

std::optional<std::string> integrity_problem(const void* data, std::size_t size) {
    char text[96];
    if (data == nullptr || size < fingerprint_size + crc_size) {
        std::snprintf(text, sizeof text, "corrupted: %zu bytes, too short for a firtp_lcm message", size);
        return text;
    }
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    const std::uint32_t sent = big_endian32(bytes + size - crc_size);
    const std::uint32_t computed = crc32(bytes, size - crc_size);
    if (sent == computed) return std::nullopt;
    std::snprintf(text, sizeof text, "corrupted: CRC mismatch (crc 0x%08" PRIx32 ", computed 0x%08" PRIx32 ")", sent,
                  computed);
    return text;
}

std::string fingerprint_note(const void* data, std::size_t size, const char* type, std::int64_t hash) {
    if (data == nullptr || size < fingerprint_size) return "";
    const std::uint64_t fingerprint = fingerprint_of(data, size);
    if (fingerprint == static_cast<std::uint64_t>(hash)) return "";
    char text[200];
    std::snprintf(text, sizeof text,
                  "; its fingerprint 0x%016" PRIx64 " is not %s's 0x%016" PRIx64 ": damaged, or another type or version",
                  fingerprint, type, static_cast<std::uint64_t>(hash));
    return text;
}

std::string not_this_type(const void* data, std::size_t size, const char* type) {
    const std::uint64_t fingerprint = fingerprint_of(data, size);
    char text[160];
    std::snprintf(text, sizeof text, "intact, but not a %s of this version (%zu bytes, fingerprint 0x%016" PRIx64 ")",
                  type, size, fingerprint);
    return text;
}

}  // namespace firtp::messages
