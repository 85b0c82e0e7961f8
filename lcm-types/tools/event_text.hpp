// One log event as one line of text: the decoded fields of the firtp_lcm types, and whether the
// message is intact (its crc).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace firtp::dump {

// What a sequence counter belongs to: the channel, and for blocks the program.
struct SeqKey {
    std::int64_t program = 0;  // 0 for the types without a program; a control's session
    std::int64_t seq = 0;
    bool config = false;       // config_t: its seq not above the last one's means the component started again
    bool session = false;      // program is a control session
};

struct EventText {
    std::string text;            // "block_t seq=3 program=7 ...", or "? 42 bytes" when unknown; a
                                 // corrupted one ends " CORRUPTED: CRC mismatch (crc 0x..., computed 0x...)"
    std::optional<SeqKey> key;   // empty when the type is unknown or the message corrupted
    bool corrupted = false;      // decodes as a firtp_lcm type, but its crc does not match
};

EventText describe(const void* data, int size);

}  // namespace firtp::dump
