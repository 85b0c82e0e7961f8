// Records of the two HAL streams between the bridge (non-real-time) and the component:
//   blocks:      bridge -> component, one record per block
//   axis states: component -> bridge, one record per servo period and group of six axes
// hal_stream records hold at most HAL_STREAM_MAX_PINS (21) elements of 32-bit ints or doubles.
#pragma once

#include <hal.h>

#include <firtp/types.hpp>

#include <firtp/hal/event_queue.hpp>

#include <cstdint>

namespace firtp::stream {

inline constexpr int default_block_key = 0x46495242;  // "FIRB"
inline constexpr int default_state_key = 0x46495253;  // "FIRS"

// target[9], feed, tolerance, line, motion type, termination, program and seq (64 bits as in
// block_t, each as low and high 32-bit halves), record kind (0 block, 1 event). An event (event_t)
// has its code in the motion type's place, its value in the feed's and its line.
inline constexpr const char* block_types = "fffffffffffsssuuuus";
inline constexpr int block_elements = 19;

struct BlockRecord {
    Block block;
    std::uint64_t program = 0;
    std::uint64_t seq = 0;       // 0 on the pins: not checked
    bool type_known = true;      // motion type and termination were valid codes (an event: its code)
    bool is_event = false;       // a program event between blocks, not a block
    std::int32_t event_code = 0; // firtp::EventKind
    double event_value = 0.0;
};

inline void pack(const BlockRecord& r, hal_stream_data* out) {
    for (int a = 0; a < max_axes; ++a) out[a].f = r.block.target[a];
    out[10].f = r.block.tolerance;
    out[9].f = r.is_event ? r.event_value : r.block.feed;
    out[11].s = static_cast<std::int32_t>(r.block.line);
    out[12].s = r.is_event ? r.event_code : static_cast<std::int32_t>(r.block.type);
    out[13].s = r.block.termination == Termination::blend ? 1 : 0;
    out[14].u = static_cast<std::uint32_t>(r.program);
    out[15].u = static_cast<std::uint32_t>(r.program >> 32);
    out[16].u = static_cast<std::uint32_t>(r.seq);
    out[17].u = static_cast<std::uint32_t>(r.seq >> 32);
    out[18].s = r.is_event ? 1 : 0;
}

// Sets type_known false when the motion type or termination is not a known code.
inline void unpack(const hal_stream_data* in, BlockRecord& r) {
    for (int a = 0; a < max_axes; ++a) r.block.target[a] = in[a].f;
    r.block.feed = in[9].f;
    r.block.tolerance = in[10].f;
    r.block.line = in[11].s;
    const std::int32_t type = in[12].s, termination = in[13].s;
    r.program = std::uint64_t{in[14].u} | std::uint64_t{in[15].u} << 32;
    r.seq = std::uint64_t{in[16].u} | std::uint64_t{in[17].u} << 32;
    r.is_event = in[18].s == 1;
    r.event_code = type;
    r.event_value = in[9].f;
    r.type_known = r.is_event ? type >= 0 && type < event_kinds : (type == 1 || type == 2) && (termination == 0 || termination == 1);
    r.block.type = type == 1 ? MotionType::traverse : MotionType::feed;
    r.block.termination = termination == 1 ? Termination::blend : Termination::exact_stop;
}

// Every period: one record per group of six axes, then one progress record.
// Axis group: tick, line, group (0: axes 0-5, 1: axes 6-8), then position, velocity, acceleration
// of six axes. Progress: tick, line, group = groups_for(axes), then the component's program and
// next_seq after the period (axis_state_t's), each as low and high 32-bit halves in a double (exact),
// then the generation of the controls applied in the period (control_pins.hpp; the bridge names
// their control_t session and seq).
inline constexpr const char* state_types = "usu" "fff" "fff" "fff" "fff" "fff" "fff";
inline constexpr int state_elements = 21;
inline constexpr int axes_per_group = 6;

inline int groups_for(int axes) { return axes > axes_per_group ? 2 : 1; }
inline int progress_group(int axes) { return groups_for(axes); }
inline int records_per_period(int axes) { return groups_for(axes) + 1; }  // the axis-state stream holds
                                                                            // stream_depth periods

struct Progress {
    std::uint64_t program = 0;
    std::uint64_t next_seq = 1;
    std::uint32_t control_gen = 0;
};

inline void pack_state(const AxisState& s, std::int64_t tick, int group, int axes, hal_stream_data* out) {
    out[0].u = static_cast<std::uint32_t>(tick);
    out[1].s = static_cast<std::int32_t>(s.line);
    out[2].u = static_cast<std::uint32_t>(group);
    for (int i = 0; i < axes_per_group; ++i) {
        const int a = group * axes_per_group + i;
        const bool used = a < axes;
        out[3 + 3 * i].f = used ? s.position[a] : 0.0;
        out[4 + 3 * i].f = used ? s.velocity[a] : 0.0;
        out[5 + 3 * i].f = used ? s.acceleration[a] : 0.0;
    }
}

inline void pack_progress(const Progress& p, std::int64_t tick, std::int32_t line, int axes, hal_stream_data* out) {
    out[0].u = static_cast<std::uint32_t>(tick);
    out[1].s = line;
    out[2].u = static_cast<std::uint32_t>(progress_group(axes));
    out[3].f = static_cast<double>(p.program & 0xffffffffu);
    out[4].f = static_cast<double>(p.program >> 32);
    out[5].f = static_cast<double>(p.next_seq & 0xffffffffu);
    out[6].f = static_cast<double>(p.next_seq >> 32);
    out[7].f = static_cast<double>(p.control_gen);
    for (int i = 8; i < state_elements; ++i) out[i].f = 0.0;
}

inline Progress unpack_progress(const hal_stream_data* in) {
    const auto half = [](double v) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)); };
    return {half(in[3].f) | half(in[4].f) << 32, half(in[5].f) | half(in[6].f) << 32, static_cast<std::uint32_t>(in[7].f)};
}

}  // namespace firtp::stream
