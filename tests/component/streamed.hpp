// A block record through the hal_stream, packed and unpacked as the bridge and firtp.so do, and a
// stream of records for ComponentLogic::update to read.
#pragma once

#include <firtp/hal/component_logic.hpp>
#include <firtp/hal/stream_records.hpp>

#include <deque>

namespace firtp::test {

inline stream::BlockRecord streamed(const stream::BlockRecord& r) {
    hal_stream_data buffer[stream::block_elements];
    stream::pack(r, buffer);
    stream::BlockRecord out;
    stream::unpack(buffer, out);
    return out;
}

// The block stream ComponentLogic reads (its BlockSource): the records queued, counting the reads.
struct FakeStream {
    std::deque<stream::BlockRecord> records;
    int reads = 0;
    static bool read(void* self, stream::BlockRecord& r) {
        auto* s = static_cast<FakeStream*>(self);
        if (s->records.empty()) return false;
        r = s->records.front();
        s->records.pop_front();
        ++s->reads;
        return true;
    }
    BlockSource source() { return {read, this}; }
};

}  // namespace firtp::test
