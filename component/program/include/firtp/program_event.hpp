// Non-motion words of a program (spindle, tool, coolant, pauses, dwell, end), as LinuxCNC's
// interpreter reports them through its canonical-machining calls, in program order between blocks.
#pragma once

#include <firtp/event_kind.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace firtp {

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
