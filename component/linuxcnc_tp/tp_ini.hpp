// tp_ini: what firtp_tp takes from the machine's INI, at load (rtapi_app_main) only: the jerk limit
// and the task's cycle time.
// LinuxCNC master's jerk-limited planner reads [TRAJ]MAX_LINEAR_JERK and [AXIS_L]MAX_JERK; so does
// firtp_tp, per axis as firtp does (ini_axis_jerk, parameters.hpp).
// Built into the firtp_tp module only: it reads with LinuxCNC's own INI reader (liblinuxcncini).
#pragma once

#include "tp_core.hpp"

#include <string>

namespace firtp::linuxcnc_tp {

struct IniJerk {
    double jerk = 0.0;     // the smallest positive value of the keys below; 0: none of them set
    std::string from;      // the key that gave it, e.g. "[TRAJ]MAX_LINEAR_JERK = 20000 (line 70)"
    // Per axis X..W: ini_axis_jerk of its keys; an axis of [TRAJ]COORDINATES without one takes
    // `jerk`; 0 where not in COORDINATES or nothing is set.
    Pose axis{};
    std::string error;     // unreadable file or a value that is not a number >= 0: file, line, key, text
};

// [TRAJ]MAX_LINEAR_JERK and [AXIS_L]MAX_JERK for the letters L of [TRAJ]COORDINATES (X..W, all nine
// without it) from the INI at `path`. 0 counts as not set, as in LinuxCNC master.
IniJerk read_ini_jerk(const char* path);

// [TASK]CYCLE_TIME in s from the INI at `path`; 0 where the file, the key or a positive number is
// missing (firtp_tp then keeps the planner's own start wait).
double read_ini_task_cycle(const char* path);

}  // namespace firtp::linuxcnc_tp
