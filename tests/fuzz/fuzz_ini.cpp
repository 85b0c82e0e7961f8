// libFuzzer target: the INI reader and the machine it describes (IniFile::parse, load_machine).
// Any input either gives a ConfigError or a machine the planner and the component accept: valid
// filter times (or, at the limits, an acceleration limit), rate settings, a positive period, finite limits; ComponentLogic takes it.
#include <firtp/hal/component_logic.hpp>
#include <firtp/fir_chain.hpp>
#include <firtp/ini.hpp>
#include <firtp/machine.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "require.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    firtp::MachineConfig m;
    firtp::PlannerParameters p;
    try {
        m = firtp::load_machine(firtp::IniFile::parse(text, "fuzz.ini"));
        p = m.planner_parameters();
    } catch (const firtp::ConfigError&) {
        return 0;  // refused with file:line: [SECTION]KEY: reason
    }
    if (p.fixed_chain) {
        require(*firtp::validate(p.filters) == '\0');
    } else {
        bool any = false;  // smoothing at the limits needs one acceleration limit
        for (int a = 0; a < p.limits.axes; ++a) any = any || p.limits.axis[a].max_acceleration > 0.0;
        require(any);
    }
    require(*firtp::validate_rate(p) == '\0');
    require(std::isfinite(p.period) && p.period > 0.0);
    require(m.default_tolerance > 0.0 && m.arc_chord_tolerance > 0.0);
    require(p.limits.axes >= 1 && p.limits.axes <= firtp::max_axes);
    for (int a = 0; a < p.limits.axes; ++a) {
        const firtp::AxisLimits& l = p.limits.axis[a];
        require(std::isfinite(l.max_velocity) && l.max_velocity >= 0.0);
        require(std::isfinite(l.max_acceleration) && l.max_acceleration >= 0.0);
        require(std::isfinite(l.max_jerk) && l.max_jerk >= 0.0);
    }
    firtp::ComponentSettings s;
    s.planner = p;
    s.axes = p.limits.axes;
    s.planner.queue_capacity = 4;
    s.default_tolerance = m.default_tolerance;
    try {
        firtp::ComponentLogic core(s);  // what firtp run / serve load with this INI
    } catch (const std::invalid_argument&) {
        std::abort();  // the INI reader accepted a machine the component refuses
    }
    return 0;
}
