// One log event as one line of text: the decoded fields of the firtp_lcm types.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace firtp::dump {

// What a sequence counter belongs to: the channel, and for blocks the program.
struct SeqKey {
    std::int64_t program = 0;  // 0 for the types without a program
    std::int64_t seq = 0;
};

struct EventText {
    std::string text;            // "block_t seq=3 program=7 ...", or "? 42 bytes" when unknown
    std::optional<SeqKey> key;   // empty when the type is unknown
};

EventText describe(const void* data, int size);

}  // namespace firtp::dump
