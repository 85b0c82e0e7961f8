// tp_ini.cpp - see tp_ini.hpp.
#include "tp_ini.hpp"

#include "inifile.hh"  // LinuxCNC's IniFile (liblinuxcncini), the reader LinuxCNC itself uses
#include <firtp/hal/module_number.hpp>
#include <firtp/parameters.hpp>

#include <cctype>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace firtp::linuxcnc_tp {
namespace {

constexpr const char* axis_letters = "XYZABCUVW";

// The axes [TRAJ]COORDINATES names (each once), or all nine.
std::string axes_of(IniFile& ini) {
    const char* coordinates = ini.Find("COORDINATES", "TRAJ");
    if (coordinates == nullptr) return axis_letters;
    std::string axes;
    for (const char* c = coordinates; *c; ++c) {
        const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
        if (std::string(axis_letters).find(upper) != std::string::npos && axes.find(upper) == std::string::npos)
            axes += upper;
    }
    return axes.empty() ? axis_letters : axes;
}

}  // namespace

IniJerk read_ini_jerk(const char* path) {
    IniJerk out;
    IniFile ini;  // errMask 0: no exceptions
    if (!ini.Open(path)) {
        out.error = std::string(path) + ": cannot be opened";
        return out;
    }
    const std::string axes = axes_of(ini);
    std::vector<std::pair<std::string, std::string>> keys{{"TRAJ", "MAX_LINEAR_JERK"}};  // section, key
    for (char axis : axes) keys.emplace_back(std::string("AXIS_") + axis, "MAX_JERK");
    std::vector<double> given(keys.size(), 0.0);  // 0: not set
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const auto& [section, key] = keys[k];
        int line = 0;
        const char* text = ini.Find(key.c_str(), section.c_str(), 1, &line);
        if (text == nullptr) continue;
        const std::optional<double> value = module_number(text);
        if (!value || *value < 0.0) {
            out.error = std::string(path) + ":" + std::to_string(line) + ": [" + section + "]" + key + " = '" + text +
                        "': not a number >= 0 (units/s^3; 0: not set)";
            return out;
        }
        given[k] = *value;
        if (*value > 0.0 && (out.jerk == 0.0 || *value < out.jerk)) {
            out.jerk = *value;
            out.from = "[" + section + "]" + key + " = " + text + " (line " + std::to_string(line) + ")";
        }
    }
    for (std::size_t k = 1; k < keys.size(); ++k) {
        const char letter = axes[k - 1];
        const double jerk = ini_axis_jerk(letter, given[k], given[0]);
        out.axis[std::string(axis_letters).find(letter)] = jerk > 0.0 ? jerk : out.jerk;
    }
    return out;
}

double read_ini_task_cycle(const char* path) {
    IniFile ini;
    if (!ini.Open(path)) return 0.0;
    const char* text = ini.Find("CYCLE_TIME", "TASK");
    if (text == nullptr) return 0.0;
    const std::optional<double> value = module_number(text);
    return value && *value > 0.0 && std::isfinite(*value) ? *value : 0.0;
}

}  // namespace firtp::linuxcnc_tp
