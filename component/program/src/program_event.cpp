#include <firtp/program_event.hpp>

namespace firtp {

std::string_view event_name(EventKind kind) {
    switch (kind) {
        case EventKind::spindle_clockwise: return "spindle_clockwise";
        case EventKind::spindle_counterclockwise: return "spindle_counterclockwise";
        case EventKind::spindle_stop: return "spindle_stop";
        case EventKind::spindle_speed: return "spindle_speed";
        case EventKind::tool_select: return "tool_select";
        case EventKind::tool_change: return "tool_change";
        case EventKind::flood_on: return "flood_on";
        case EventKind::mist_on: return "mist_on";
        case EventKind::coolant_off: return "coolant_off";
        case EventKind::pause: return "pause";
        case EventKind::optional_pause: return "optional_pause";
        case EventKind::dwell: return "dwell";
        case EventKind::program_end: return "program_end";
    }
    return "unknown";
}

// LinuxCNC 2.9's task holds a tool change, a pause, a dwell, every spindle and coolant command
// until motion has finished (emcTaskCheckPreconditions: WAITING_FOR_MOTION_AND_IO); a T word only
// waits for the tool changer. The end needs no wait of its own: the program's last block stops,
// whatever its termination.
bool event_waits(EventKind kind) {
    switch (kind) {
        case EventKind::tool_select:
        case EventKind::program_end: return false;
        default: return true;
    }
}

}  // namespace firtp
