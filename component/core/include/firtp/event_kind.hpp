// The non-motion words of a program, one vocabulary for every layer: LinuxCNC's interpreter
// reports them (program_event.hpp), the host sends them (firtp_lcm::event_t, whose kind constants
// are these values), and firtp.so fires them (event_queue.hpp). Values are the protocol's.
#pragma once

#include <cstdint>

namespace firtp {

enum class EventKind : std::uint8_t {
    spindle_clockwise = 0,         // M3          value: spindle speed (rpm) in force
    spindle_counterclockwise = 1,  // M4          value: spindle speed (rpm)
    spindle_stop = 2,              // M5
    spindle_speed = 3,             // S           value: rpm
    tool_select = 4,               // T           value: tool number
    tool_change = 5,               // M6          value: tool number now in the spindle
    flood_on = 6,                  // M8
    mist_on = 7,                   // M7
    coolant_off = 8,               // M9 (flood and mist off)
    pause = 9,                     // M0, M60
    optional_pause = 10,           // M1
    dwell = 11,                    // G4          value: seconds
    program_end = 12,              // M2, M30
};
constexpr int event_kinds = 13;

}  // namespace firtp
