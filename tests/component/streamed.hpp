// A block record through the hal_stream, packed and unpacked as the bridge and firtp.so do.
#pragma once

#include <firtp/hal/stream_records.hpp>

namespace firtp::test {

inline stream::BlockRecord streamed(const stream::BlockRecord& r) {
    hal_stream_data buffer[stream::block_elements];
    stream::pack(r, buffer);
    stream::BlockRecord out;
    stream::unpack(buffer, out);
    return out;
}

}  // namespace firtp::test
