// The canonical-machining functions and globals a program linking LinuxCNC's librs274 defines
// (as LinuxCNC's src/emc/sai does for `rs274`), forwarding to the active CanonRecorder. Calls that
// only matter to a real machine (I/O bits, overrides, logging) do nothing; probing and
// spindle-synchronised motion are refused (firtp cannot plan them).
#include "rs274_canon.hpp"

#include "canon_recorder.hpp"

#include <canon.hh>
#include "tooldata.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>

using firtp::AxisVector;
using firtp::EventKind;

namespace {

firtp::gcode::CanonRecorder* active = nullptr;
std::string parameter_file;
bool optional_stop = true;
bool block_delete = true;
int axis_mask = 0x7;

firtp::gcode::CanonRecorder& rec() { return *active; }

AxisVector vec(double x, double y, double z, double a, double b, double c, double u, double v, double w) {
    AxisVector p;
    p << x, y, z, a, b, c, u, v, w;
    return p;
}

AxisVector vec(const EmcPose& p) { return vec(p.tran.x, p.tran.y, p.tran.z, p.a, p.b, p.c, p.u, p.v, p.w); }

double position(int axis) { return active != nullptr ? rec().program_position()[axis] : 0.0; }
double tool_offset(int axis) { return active != nullptr ? rec().tool_offset_program()[axis] : 0.0; }

}  // namespace

namespace firtp::gcode {

void set_canon_recorder(CanonRecorder* recorder) { active = recorder; }
void set_canon_parameter_file(const std::string& path) { parameter_file = path; }
void set_canon_axes(int axes) { axis_mask = (1 << axes) - 1; }

}  // namespace firtp::gcode

// Globals librs274 refers to.
int _task = 0;  // 0: not LinuxCNC's task (remaps behave as in a preview)
USER_DEFINED_FUNCTION_TYPE USER_DEFINED_FUNCTION[USER_DEFINED_FUNCTION_NUM] = {nullptr};
int USER_DEFINED_FUNCTION_ADD(USER_DEFINED_FUNCTION_TYPE func, int num) {
    if (num < 0 || num >= USER_DEFINED_FUNCTION_NUM) return -1;
    USER_DEFINED_FUNCTION[num] = func;
    return 0;
}
// Python modules built into the interpreter's plugin, as rs274 has them (Python.h's _inittab layout):
// librs274's own `interpreter` module, which the plugin imports at start.
extern "C" void* PyInit_interpreter();
struct _inittab {
    const char* name;
    void* (*initfunc)();
};
struct _inittab builtin_modules[] = {{"interpreter", PyInit_interpreter}, {nullptr, nullptr}};

// Representation
void INIT_CANON() {}
void SET_G5X_OFFSET(int, double x, double y, double z, double a, double b, double c, double u, double v, double w) {
    rec().set_g5x(vec(x, y, z, a, b, c, u, v, w));
}
void SET_G92_OFFSET(double x, double y, double z, double a, double b, double c, double u, double v, double w) {
    rec().set_g92(vec(x, y, z, a, b, c, u, v, w));
}
void SET_XY_ROTATION(double t) { rec().set_xy_rotation(t); }
void CANON_UPDATE_END_POINT(double, double, double, double, double, double, double, double, double) {}
void USE_LENGTH_UNITS(CANON_UNITS u) {
    if (u == CANON_UNITS_CM) rec().refuse("length units of cm");
    rec().set_units_inch(u == CANON_UNITS_INCHES);
}
CANON_PLANE plane = CANON_PLANE_XY;
void SELECT_PLANE(CANON_PLANE pl) { plane = pl; }

// Free space motion
void SET_TRAVERSE_RATE(double) {}  // G0 runs at the axes' limits
void STRAIGHT_TRAVERSE(int line, double x, double y, double z, double a, double b, double c, double u, double v,
                       double w) {
    rec().straight(true, line, vec(x, y, z, a, b, c, u, v, w));
}

// Machining attributes
void SET_FEED_RATE(double rate) { rec().set_feed_rate(rate); }
void SET_FEED_REFERENCE(CANON_FEED_REFERENCE) {}
void SET_FEED_MODE(int, int mode) { rec().set_feed_per_revolution(mode == 1); }
void SET_MOTION_CONTROL_MODE(CANON_MOTION_MODE mode, double tolerance) {
    if (mode == CANON_CONTINUOUS) rec().set_blend(tolerance);
    else rec().set_exact_stop();
}
void SET_NAIVECAM_TOLERANCE(double tolerance) { rec().set_naive_cam(tolerance); }
void SET_CUTTER_RADIUS_COMPENSATION(double) {}  // the interpreter offsets the path itself
void START_CUTTER_RADIUS_COMPENSATION(int) {}
void STOP_CUTTER_RADIUS_COMPENSATION() {}
void START_SPEED_FEED_SYNCH(int, double, bool) { rec().refuse("spindle-synchronised motion (G33, G76, G95 sync)"); }
void STOP_SPEED_FEED_SYNCH() { rec().end_chain(); }

// Machining functions
void ARC_FEED(int line, double first_end, double second_end, double first_axis, double second_axis, int rotation,
              double axis_end_point, double a, double b, double c, double u, double v, double w) {
    const int code = plane == CANON_PLANE_YZ ? 190 : plane == CANON_PLANE_XZ ? 180 : 170;
    if (plane != CANON_PLANE_XY && plane != CANON_PLANE_YZ && plane != CANON_PLANE_XZ)
        return rec().refuse("an arc in the UV, VW or UW plane");
    rec().arc(line, code, first_end, second_end, first_axis, second_axis, rotation, axis_end_point,
              vec(0, 0, 0, a, b, c, u, v, w));
}
void STRAIGHT_FEED(int line, double x, double y, double z, double a, double b, double c, double u, double v,
                   double w) {
    rec().straight(false, line, vec(x, y, z, a, b, c, u, v, w));
}
void NURBS_FEED(int, std::vector<CONTROL_POINT>, unsigned int) { rec().refuse("a NURBS curve (G5.2)"); }
void RIGID_TAP(int, double, double, double, double) { rec().refuse("rigid tapping (G33.1)"); }
void STRAIGHT_PROBE(int, double, double, double, double, double, double, double, double, double, unsigned char) {
    rec().refuse("probing (G38)");
}
void STOP() {}
void DWELL(double seconds) { rec().event(EventKind::dwell, seconds); }

// Spindle functions
void SET_SPINDLE_MODE(int, double) {}
void SPINDLE_RETRACT_TRAVERSE() {}
void START_SPINDLE_CLOCKWISE(int, int) { rec().spindle_start(true); }
void START_SPINDLE_COUNTERCLOCKWISE(int, int) { rec().spindle_start(false); }
void SET_SPINDLE_SPEED(int, double r) { rec().spindle_speed(r); }
void STOP_SPINDLE_TURNING(int) { rec().spindle_stop(); }
void SPINDLE_RETRACT() {}
void ORIENT_SPINDLE(int, double, int) { rec().motion_waits(); }
void WAIT_SPINDLE_ORIENT_COMPLETE(int, double) { rec().motion_waits(); }
void LOCK_SPINDLE_Z() {}
void USE_SPINDLE_FORCE() {}
void USE_NO_SPINDLE_FORCE() {}

// Tool functions: the table lives in libtooldata (loaded by the reader); index 0 is the spindle.
void SET_TOOL_TABLE_ENTRY(int idx, int toolno, EmcPose offset, double diameter, double frontangle, double backangle,
                          int orientation) {
    rec().motion_waits();
    CANON_TOOL_TABLE t;
    if (tooldata_get(&t, idx) != IDX_OK) return;
    t.toolno = toolno;
    t.offset = offset;
    t.diameter = diameter;
    t.frontangle = frontangle;
    t.backangle = backangle;
    t.orientation = orientation;
    tooldata_put(t, idx);
}
void USE_TOOL_LENGTH_OFFSET(EmcPose offset) { rec().set_tool_offset(vec(offset)); }
void CHANGE_TOOL(int slot) {
    CANON_TOOL_TABLE t;
    if (tooldata_get(&t, slot) != IDX_OK) return rec().refuse("a tool change to an index the tool table lacks");
    tooldata_put(t, 0);
    rec().change_tool(t.toolno);
}
void SELECT_TOOL(int tool) { rec().select_tool(tool); }
void CHANGE_TOOL_NUMBER(int number) {
    CANON_TOOL_TABLE t;
    if (tooldata_get(&t, number) == IDX_OK) tooldata_put(t, 0);
}
void RELOAD_TOOLDATA() {}
void START_CHANGE() { rec().motion_waits(); }

// Miscellaneous
void CLAMP_AXIS(CANON_AXIS) {}
void UNCLAMP_AXIS(CANON_AXIS) {}
void COMMENT(const char*) {}
void DISABLE_ADAPTIVE_FEED() { rec().motion_waits(); }
void ENABLE_ADAPTIVE_FEED() { rec().motion_waits(); }
void DISABLE_FEED_OVERRIDE() { rec().end_chain(); }
void ENABLE_FEED_OVERRIDE() { rec().end_chain(); }
void DISABLE_SPEED_OVERRIDE(int) { rec().end_chain(); }
void ENABLE_SPEED_OVERRIDE(int) { rec().end_chain(); }
void DISABLE_FEED_HOLD() { rec().end_chain(); }
void ENABLE_FEED_HOLD() { rec().end_chain(); }
void FLOOD_OFF() { rec().coolant(EventKind::coolant_off); }
void FLOOD_ON() { rec().coolant(EventKind::flood_on); }
void MESSAGE(char*) { rec().motion_waits(); }
void LOG(char*) { rec().end_chain(); }
void LOGOPEN(char*) {}
void LOGAPPEND(char*) {}
void LOGCLOSE() {}
void MIST_OFF() { rec().coolant(EventKind::coolant_off); }
void MIST_ON() { rec().coolant(EventKind::mist_on); }
void PALLET_SHUTTLE() {}
void TURN_PROBE_OFF() {}
void TURN_PROBE_ON() {}
void NURB_KNOT_VECTOR() {}
void NURB_CONTROL_POINT(int, double, double, double, double) {}
void NURB_FEED(double, double) {}
void SET_BLOCK_DELETE(bool enabled) { block_delete = enabled; }
bool GET_BLOCK_DELETE() { return block_delete; }
void OPTIONAL_PROGRAM_STOP() { rec().event(EventKind::optional_pause); }
void SET_OPTIONAL_PROGRAM_STOP(bool state) { optional_stop = state; }
bool GET_OPTIONAL_PROGRAM_STOP() { return optional_stop; }
void PROGRAM_END() { rec().event(EventKind::program_end); }
void PROGRAM_STOP() { rec().event(EventKind::pause); }
void SET_MOTION_OUTPUT_BIT(int) { rec().end_chain(); }
void CLEAR_MOTION_OUTPUT_BIT(int) { rec().end_chain(); }
void SET_AUX_OUTPUT_BIT(int) { rec().motion_waits(); }
void CLEAR_AUX_OUTPUT_BIT(int) { rec().motion_waits(); }
void SET_MOTION_OUTPUT_VALUE(int, double) { rec().end_chain(); }
void SET_AUX_OUTPUT_VALUE(int, double) { rec().motion_waits(); }
int WAIT(int, int, int, double) { return rec().motion_waits(), 0; }
int UNLOCK_ROTARY(int, int) { return 0; }
int LOCK_ROTARY(int, int) { return 0; }
void FINISH() {}
void ON_RESET() {}
void CANON_ERROR(const char* fmt, ...) {
    char text[256];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (active != nullptr) rec().refuse(text);
}
void PLUGIN_CALL(int, const char*) {}
void IO_PLUGIN_CALL(int, const char*) {}
void UPDATE_TAG(StateTag) {}

// The world model the interpreter asks about.
double GET_EXTERNAL_ANGLE_UNIT_FACTOR() { return 1.0; }
double GET_EXTERNAL_ANGLE_UNITS() { return 1.0; }
double GET_EXTERNAL_FEED_RATE() { return active != nullptr ? rec().feed_rate_program() : 0.0; }
int GET_EXTERNAL_FLOOD() { return active != nullptr && rec().flood(); }
int GET_EXTERNAL_MIST() { return active != nullptr && rec().mist(); }
double GET_EXTERNAL_LENGTH_UNIT_FACTOR() { return 1.0; }
double GET_EXTERNAL_LENGTH_UNITS() { return 1.0; }  // machine units per mm: firtp's machine is in mm
CANON_UNITS GET_EXTERNAL_LENGTH_UNIT_TYPE() { return CANON_UNITS_MM; }
CANON_MOTION_MODE GET_EXTERNAL_MOTION_CONTROL_MODE() {
    return active != nullptr && rec().exact_stop() ? CANON_EXACT_PATH : CANON_CONTINUOUS;
}
double GET_EXTERNAL_MOTION_CONTROL_TOLERANCE() { return active != nullptr ? rec().tolerance_program() : 0.0; }
double GET_EXTERNAL_MOTION_CONTROL_NAIVECAM_TOLERANCE() { return active != nullptr ? rec().naive_cam_program() : 0.0; }
void GET_EXTERNAL_PARAMETER_FILE_NAME(char* filename, int max_size) {
    std::snprintf(filename, static_cast<std::size_t>(max_size), "%s", parameter_file.c_str());
}
void SET_PARAMETER_FILE_NAME(const char* name) { parameter_file = name; }
CANON_PLANE GET_EXTERNAL_PLANE() { return plane; }
double GET_EXTERNAL_POSITION_X() { return position(0); }
double GET_EXTERNAL_POSITION_Y() { return position(1); }
double GET_EXTERNAL_POSITION_Z() { return position(2); }
double GET_EXTERNAL_POSITION_A() { return position(3); }
double GET_EXTERNAL_POSITION_B() { return position(4); }
double GET_EXTERNAL_POSITION_C() { return position(5); }
double GET_EXTERNAL_POSITION_U() { return position(6); }
double GET_EXTERNAL_POSITION_V() { return position(7); }
double GET_EXTERNAL_POSITION_W() { return position(8); }
double GET_EXTERNAL_PROBE_POSITION_X() { return position(0); }
double GET_EXTERNAL_PROBE_POSITION_Y() { return position(1); }
double GET_EXTERNAL_PROBE_POSITION_Z() { return position(2); }
double GET_EXTERNAL_PROBE_POSITION_A() { return position(3); }
double GET_EXTERNAL_PROBE_POSITION_B() { return position(4); }
double GET_EXTERNAL_PROBE_POSITION_C() { return position(5); }
double GET_EXTERNAL_PROBE_POSITION_U() { return position(6); }
double GET_EXTERNAL_PROBE_POSITION_V() { return position(7); }
double GET_EXTERNAL_PROBE_POSITION_W() { return position(8); }
double GET_EXTERNAL_PROBE_VALUE() { return 0.0; }
int GET_EXTERNAL_PROBE_TRIPPED_VALUE() { return 0; }
int GET_EXTERNAL_QUEUE_EMPTY() { return 1; }
double GET_EXTERNAL_SPEED(int) { return active != nullptr ? rec().spindle_rpm() : 0.0; }
CANON_DIRECTION GET_EXTERNAL_SPINDLE(int) {
    const int d = active != nullptr ? rec().spindle_direction() : 0;
    return d > 0 ? CANON_CLOCKWISE : d < 0 ? CANON_COUNTERCLOCKWISE : CANON_STOPPED;
}
double GET_EXTERNAL_TOOL_LENGTH_XOFFSET() { return tool_offset(0); }
double GET_EXTERNAL_TOOL_LENGTH_YOFFSET() { return tool_offset(1); }
double GET_EXTERNAL_TOOL_LENGTH_ZOFFSET() { return tool_offset(2); }
double GET_EXTERNAL_TOOL_LENGTH_AOFFSET() { return tool_offset(3); }
double GET_EXTERNAL_TOOL_LENGTH_BOFFSET() { return tool_offset(4); }
double GET_EXTERNAL_TOOL_LENGTH_COFFSET() { return tool_offset(5); }
double GET_EXTERNAL_TOOL_LENGTH_UOFFSET() { return tool_offset(6); }
double GET_EXTERNAL_TOOL_LENGTH_VOFFSET() { return tool_offset(7); }
double GET_EXTERNAL_TOOL_LENGTH_WOFFSET() { return tool_offset(8); }
int GET_EXTERNAL_TOOL_SLOT() { return 0; }
int GET_EXTERNAL_SELECTED_TOOL_SLOT() { return 0; }
CANON_TOOL_TABLE GET_EXTERNAL_TOOL_TABLE(int idx) {
    CANON_TOOL_TABLE t = tooldata_entry_init();
    if (tooldata_get(&t, idx) != IDX_OK) t = tooldata_entry_init();
    return t;
}
int GET_EXTERNAL_TC_FAULT() { return 0; }
int GET_EXTERNAL_TC_REASON() { return 0; }
double GET_EXTERNAL_TRAVERSE_RATE() { return 0.0; }
int GET_EXTERNAL_FEED_OVERRIDE_ENABLE() { return 1; }
int GET_EXTERNAL_SPINDLE_OVERRIDE_ENABLE(int) { return 1; }
int GET_EXTERNAL_ADAPTIVE_FEED_ENABLE() { return 0; }
int GET_EXTERNAL_FEED_HOLD_ENABLE() { return 1; }
int GET_EXTERNAL_DIGITAL_INPUT(int, int def) { return def; }
double GET_EXTERNAL_ANALOG_INPUT(int, double def) { return def; }
int GET_EXTERNAL_AXIS_MASK() { return axis_mask; }
int GET_EXTERNAL_OFFSET_APPLIED() { return 0; }
EmcPose GET_EXTERNAL_OFFSETS() { return EmcPose{}; }
