// Non-motion words of a program (spindle, tool, coolant, pauses, dwell, end), as LinuxCNC's
// interpreter reports them through its canonical-machining calls, in program order between blocks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace firtp {

enum class EventKind : std::uint8_t {
    spindle_clockwise,         // M3          value: spindle speed (rpm) in force
    spindle_counterclockwise,  // M4          value: spindle speed (rpm)
    spindle_stop,              // M5
    spindle_speed,             // S           value: rpm
    tool_select,               // T           value: tool number
    tool_change,               // M6          value: tool number now in the spindle
    flood_on,                  // M8
    mist_on,                   // M7
    coolant_off,               // M9 (flood and mist off)
    pause,                     // M0, M60
    optional_pause,            // M1
    dwell,                     // G4          value: seconds
    program_end,               // M2, M30
};
constexpr int event_kinds = 13;

std::string_view event_name(EventKind kind);  // "spindle_clockwise", ... (JSON, summary)

// Motion waits here as LinuxCNC's task does: the block before ends in an exact stop.
bool event_waits(EventKind kind);

struct ProgramEvent {
    EventKind kind = EventKind::program_end;
    double value = 0.0;
    std::size_t before_block = 0;  // happens after blocks [0, before_block) and before the rest
    std::string file;              // where the word was (a subroutine's file for O-word calls)
    std::int64_t line = 0;
};

}  // namespace firtp
