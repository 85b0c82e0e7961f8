// The operator controls (feed-scale, hold, abort) go from the LCM bridge to firtp.update on three
// pins, and a fourth, control-gen, says which control they came from, so that every axis state can
// name the control applied in its period (axis_state_t control_session, control_seq;
// lcm-types/README.md). The bridge (the only writer, not real-time) and the servo thread read and
// write them at the same time, so control-gen works as a sequence lock:
//
//   writer: control-gen odd, then the three levels, then control-gen even (two more than before);
//   reader: control-gen, the three levels, control-gen again; the levels count only when both
//           reads were the same even value, else the reader keeps the levels it applied last
//           (the new ones follow a period later, named with their generation then).
//
// So the levels firtp.update applies always belong to the generation it reports, never half of
// one control and half of another. Generation g (even) is the bridge's (g / 2)-th control taken;
// 0: none, and an unconnected control-gen stays 0, so levels set by other HAL components are
// applied as they are, every period. Lock-free: two loads and two fences more per period for the
// reader, no waiting on either side.
#pragma once

#include <firtp/hal/hal_pin_access.hpp>

#include <hal.h>

#include <cstdint>

namespace firtp::control_pins {

struct Levels {
    double feed_scale = 1.0;
    bool hold = false;
    bool abort = false;
};

struct Pins {
    hal_u32_t* gen;  // HAL's pin types are volatile already
    hal_float_t* feed_scale;
    hal_bit_t* hold;
    hal_bit_t* abort;
};

// The bridge: publishes `levels` as generation `gen` + 2 (gen: the even value it wrote last) and
// returns that generation.
inline std::uint32_t write(const Pins& p, std::uint32_t gen, const Levels& levels) {
    hal_pin::set(p.gen, gen + 1);
    __atomic_thread_fence(__ATOMIC_RELEASE);
    hal_pin::set(p.feed_scale, levels.feed_scale);
    hal_pin::set(p.hold, levels.hold);
    hal_pin::set(p.abort, levels.abort);
    __atomic_thread_fence(__ATOMIC_RELEASE);
    hal_pin::set(p.gen, gen + 2);
    return gen + 2;
}

// The servo thread: true and `levels`, `gen` set when the pins hold one whole generation; false
// (both left as they were) while the bridge writes.
inline bool read(const Pins& p, Levels& levels, std::uint32_t& gen) {
    const std::uint32_t before = hal_pin::get(p.gen);
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    const Levels read{hal_pin::get(p.feed_scale), hal_pin::get(p.hold) != 0, hal_pin::get(p.abort) != 0};
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    const std::uint32_t after = hal_pin::get(p.gen);
    if (before != after || (before & 1u) != 0) return false;
    levels = read;
    gen = before;
    return true;
}

}  // namespace firtp::control_pins
