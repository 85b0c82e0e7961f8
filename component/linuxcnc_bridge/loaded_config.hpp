// FIRTP_CONFIG for firtp.so in LinuxCNC's HAL (mode firtp): its settings in effect, read from its
// read-only HAL params (`halcmd show param firtp`), so that a recorded log replays with nothing else.
#pragma once

#include <firtp_lcm/config_t.hpp>

namespace firtp {

// command "loadrt": args are the loadrt words (one a line) that load firtp.so again with the same
// settings, all but queue, max_blocks, plan_budget_us and stream_depth (their own fields); ini_file
// and ini_text are LinuxCNC's INI ($INI_FILE_NAME, set by the linuxcnc launcher) for the reader.
// Throws std::runtime_error naming a param firtp.so does not have (not loaded before the bridge).
firtp_lcm::config_t loaded_firtp_config();

}  // namespace firtp
