#include <firtp/machine.hpp>

#include <firtp/text_cat.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace firtp {
namespace {

[[noreturn]] void fail(const IniFile& ini, const IniFile::Entry& e, const std::string& message) {
    throw ConfigError(cat(ini.file_name(), ":", std::to_string(e.line), ": [", e.section, "]", e.key, ": ", message));
}

// Reads a key that, when present, must be a number > 0 (or >= 0 when zero_allowed).
std::optional<double> positive(const IniFile& ini, std::string_view section, std::string_view key,
                               bool zero_allowed = false) {
    const auto value = ini.number(section, key);
    if (value && (*value < 0.0 || (*value == 0.0 && !zero_allowed))) {
        const IniFile::Entry& e = *ini.find(section, key);
        fail(ini, e, cat("'", e.value, "' must be ", zero_allowed ? "zero or positive" : "positive"));
    }
    return value;
}

void read_period(const IniFile& ini, MachineConfig& m) {
    const auto ns = positive(ini, "EMCMOT", "SERVO_PERIOD");
    if (!ns) return;
    if (*ns != std::floor(*ns)) fail(ini, *ini.find("EMCMOT", "SERVO_PERIOD"), "must be a whole number of nanoseconds");
    m.period = *ns * 1e-9;
}

void read_axes(const IniFile& ini, MachineConfig& m) {
    if (const auto v = positive(ini, "TRAJ", "MAX_LINEAR_VELOCITY")) m.limits.max_linear_velocity = *v;
    for (int i = 0; i < max_axes; ++i) {
        const std::string section = std::string("AXIS_") + axis_letters[static_cast<std::size_t>(i)];
        if (ini.section(section).empty()) continue;
        m.limits.axes = std::max(m.limits.axes, i + 1);
        AxisLimits& axis = m.limits.axis[static_cast<std::size_t>(i)];
        if (const auto v = positive(ini, section, "MAX_VELOCITY")) axis.max_velocity = *v;
        if (const auto v = positive(ini, section, "MAX_ACCELERATION")) axis.max_acceleration = *v;
        if (const auto v = positive(ini, section, "MAX_JERK", true)) axis.max_jerk = *v;  // 0 = not limited
    }
}

std::vector<double> read_modes(const IniFile& ini, const IniFile::Entry& e) {
    std::vector<double> modes;
    std::istringstream words(e.value);
    for (std::string word; words >> word;) {
        double hz = 0.0;
        const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), hz);
        if (ec != std::errc{} || ptr != word.data() + word.size() || !std::isfinite(hz))
            fail(ini, e, cat("'", word, "' is not a number"));
        if (hz <= 0.0) fail(ini, e, cat("'", word, "' must be a positive frequency in Hz"));
        modes.push_back(hz);
    }
    return modes;
}

void read_firtp(const IniFile& ini, MachineConfig& m) {
    static constexpr std::string_view known[] = {"STAGES",    "T1", "T2", "T3", "T4", "MODES",
                                                 "TOLERANCE", "TOLERANCE_MEANING", "ARC_CHORD_TOLERANCE",
                                                 "RATE_RESERVE"};
    for (const IniFile::Entry* e : ini.section("FIRTP"))
        if (std::find(std::begin(known), std::end(known), e->key) == std::end(known))
            fail(ini, *e,
                 "unknown key (known: STAGES, T1..T4, MODES, TOLERANCE, TOLERANCE_MEANING, ARC_CHORD_TOLERANCE, "
                 "RATE_RESERVE)");
    if (const auto r = positive(ini, "FIRTP", "RATE_RESERVE")) {
        if (*r >= 1.0) fail(ini, *ini.find("FIRTP", "RATE_RESERVE"), "must be below 1 (a share of the acceleration and jerk limits)");
        m.rate_reserve = *r;
    }
    if (const auto o = positive(ini, "DISPLAY", "MAX_FEED_OVERRIDE")) {
        if (*o < 1.0) fail(ini, *ini.find("DISPLAY", "MAX_FEED_OVERRIDE"), "must be at least 1 (100 %)");
        m.max_feed_override = *o;
    }

    if (const auto stages = ini.number("FIRTP", "STAGES")) {
        if (*stages != std::floor(*stages) || *stages < 1 || *stages > max_stages)
            fail(ini, *ini.find("FIRTP", "STAGES"), "must be a whole number from 1 to 4");
        m.stages = static_cast<int>(*stages);
    }
    for (std::size_t i = 0; i < max_stages; ++i) {
        const auto t = positive(ini, "FIRTP", cat("T", std::to_string(i + 1)));
        if (!t) continue;
        if (m.given_times.size() <= i) m.given_times.resize(i + 1, 0.0);
        m.given_times[i] = *t;
    }
    if (const IniFile::Entry* e = ini.find("FIRTP", "MODES")) m.mode_frequencies = read_modes(ini, *e);
    if (const auto tol = positive(ini, "FIRTP", "TOLERANCE")) m.default_tolerance = *tol;
    if (const auto chord = positive(ini, "FIRTP", "ARC_CHORD_TOLERANCE")) m.arc_chord_tolerance = *chord;
    if (const IniFile::Entry* e = ini.find("FIRTP", "TOLERANCE_MEANING")) {
        std::string v = e->value;
        std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (v == "corner") m.tolerance_meaning = ToleranceMeaning::corner_point;
        else if (v == "contour") m.tolerance_meaning = ToleranceMeaning::contour;
        else fail(ini, *e, cat("'", e->value, "' must be corner or contour"));
    }
}

void check_override(const std::optional<double>& value, const char* flag, const char* what) {
    if (value && !(std::isfinite(*value) && *value > 0.0))
        throw ConfigError(cat(flag, ": must be a positive ", what));
}

}  // namespace

FilterTimes MachineConfig::filter_times() const {
    try {
        return filter_times_from_limits(limits, stages, given_times, mode_frequencies);
    } catch (const std::invalid_argument& e) {
        throw ConfigError(cat("filter times: ", e.what()));
    }
}

PlannerParameters MachineConfig::planner_parameters() const {
    PlannerParameters p;
    p.filters = filter_times();
    p.period = period;
    p.tolerance_meaning = tolerance_meaning;
    p.limits = limits;
    p.max_rate = max_feed_override;
    p.rate_reserve = rate_reserve;
    return p;
}

MachineConfig default_machine() {
    MachineConfig m;
    m.period = 0.001;
    m.limits.axes = 3;
    m.limits.max_linear_velocity = 0.0;
    for (std::size_t i = 0; i < 3; ++i) m.limits.axis[i] = AxisLimits{300.0, 5000.0, 100000.0};
    m.stages = 2;
    m.default_tolerance = 0.05;
    m.tolerance_meaning = ToleranceMeaning::corner_point;
    m.arc_chord_tolerance = 0.001;
    return m;
}

MachineConfig load_machine(const IniFile& ini) {
    MachineConfig m = default_machine();
    read_period(ini, m);
    read_axes(ini, m);
    read_firtp(ini, m);
    return m;
}

void apply_overrides(MachineConfig& machine, const MachineOverrides& o) {
    check_override(o.t1, "--t1", "number of seconds");
    check_override(o.t2, "--t2", "number of seconds");
    check_override(o.tolerance, "--tolerance", "length in mm");
    check_override(o.period, "--period", "number of seconds");
    if (o.t1) {
        if (machine.given_times.empty()) machine.given_times.resize(1, 0.0);
        machine.given_times[0] = *o.t1;
    }
    if (o.t2) {
        if (machine.given_times.size() < 2) machine.given_times.resize(2, 0.0);
        machine.given_times[1] = *o.t2;
        machine.stages = std::max(machine.stages, 2);
    }
    if (o.tolerance) machine.default_tolerance = *o.tolerance;
    if (o.period) machine.period = *o.period;
}

}  // namespace firtp
