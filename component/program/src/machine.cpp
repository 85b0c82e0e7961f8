#include <firtp/machine.hpp>

#include <firtp/text_cat.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <array>
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

// Reads a key that, when present, must be a whole number from lo to hi (`range` says it: "1 to 4").
std::optional<double> whole(const IniFile& ini, std::string_view section, std::string_view key, double lo, double hi,
                            const char* range) {
    const auto value = ini.number(section, key);
    if (value && (*value != std::floor(*value) || *value < lo || *value > hi))
        fail(ini, *ini.find(section, key), cat("must be a whole number from ", range));
    return value;
}

// Hands a key's text, when present, to `parse`; its ConfigError is refused naming the key.
template <class Parse>
void parse_key(const IniFile& ini, std::string_view section, std::string_view key, Parse&& parse) {
    const IniFile::Entry* e = ini.find(section, key);
    if (e == nullptr) return;
    try {
        parse(e->value);
    } catch (const ConfigError& error) {
        fail(ini, *e, error.what());
    }
}

void read_period(const IniFile& ini, MachineConfig& m) {
    const auto ns = positive(ini, "EMCMOT", "SERVO_PERIOD");
    if (!ns) return;
    if (*ns != std::floor(*ns)) fail(ini, *ini.find("EMCMOT", "SERVO_PERIOD"), "must be a whole number of nanoseconds");
    m.period = *ns * 1e-9;
}

// A key in [AXIS_<L>] that looks like a limit but is none firtp or LinuxCNC knows would leave the
// built-in limit in force (MAX_ACCELLERATION = 500 would plan at 5000 units/s^2): refused. Other
// keys (LinuxCNC's MIN_LIMIT, FERROR, ...) are not firtp's business.
void check_axis_keys(const IniFile& ini, const std::string& section) {
    static constexpr std::string_view known[] = {"MAX_VELOCITY", "MAX_ACCELERATION", "MAX_JERK", "MAX_LIMIT",
                                                 "MAX_OUTPUT"};
    for (const IniFile::Entry* e : ini.section(section)) {
        if (std::find(std::begin(known), std::end(known), e->key) != std::end(known)) continue;
        std::string upper = e->key;
        std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        if (upper.rfind("MAX_", 0) == 0 || upper.rfind("MAX", 0) == 0)
            fail(ini, *e, "unknown limit key (firtp reads MAX_VELOCITY, MAX_ACCELERATION, MAX_JERK; keys are case sensitive)");
    }
}

// [TRAJ]COORDINATES, as LinuxCNC reads it, names the machine's axes (a letter twice is a gantry:
// one axis here); nullptr when the INI has none.
const IniFile::Entry* coordinates(const IniFile& ini, std::array<bool, max_axes>& named) {
    const IniFile::Entry* e = ini.find("TRAJ", "COORDINATES");
    if (e == nullptr) return nullptr;
    named.fill(false);
    for (const char c : e->value) {
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        const auto at = std::find(axis_letters.begin(), axis_letters.end(), upper);
        if (at == axis_letters.end()) fail(ini, *e, cat("'", std::string(1, c), "' is not an axis letter (X Y Z A B C U V W)"));
        named[static_cast<std::size_t>(at - axis_letters.begin())] = true;
    }
    return e;
}

// Any axis COORDINATES does not name is one the machine does not have: its moves are refused when
// planned (Planner::add), whatever [AXIS_L] or the built-in machine says.
void read_coordinates(const IniFile& ini, MachineConfig& m) {
    std::array<bool, max_axes> named{};
    if (coordinates(ini, named) == nullptr) return;
    for (int i = 0; i < max_axes; ++i) {
        if (named[static_cast<std::size_t>(i)]) m.limits.axes = std::max(m.limits.axes, i + 1);
        else m.limits.axis[i] = AxisLimits{0.0, 0.0, 0.0};
    }
}

void read_axes(const IniFile& ini, MachineConfig& m) {
    if (const auto v = positive(ini, "TRAJ", "MAX_LINEAR_VELOCITY")) m.limits.max_linear_velocity = *v;
    double linear_jerk = 0.0;  // 0: not set
    if (const auto v = positive(ini, "TRAJ", "MAX_LINEAR_JERK", true)) linear_jerk = *v;
    bool own_jerk[max_axes] = {};  // [AXIS_L]MAX_JERK given
    for (int i = 0; i < max_axes; ++i) {
        const std::string section = std::string("AXIS_") + axis_letters[i];
        if (ini.section(section).empty()) continue;
        check_axis_keys(ini, section);
        m.limits.axes = std::max(m.limits.axes, i + 1);
        AxisLimits& axis = m.limits.axis[i];
        if (const auto v = positive(ini, section, "MAX_VELOCITY")) axis.max_velocity = *v;
        if (const auto v = positive(ini, section, "MAX_ACCELERATION")) axis.max_acceleration = *v;
        if (const auto v = positive(ini, section, "MAX_JERK", true)) axis.max_jerk = *v, own_jerk[i] = true;  // 0 = not limited
    }
    read_coordinates(ini, m);
    // LinuxCNC master's jerk-limited planner reads [TRAJ]MAX_LINEAR_JERK beside [AXIS_L]MAX_JERK; so do
    // firtp and firtp_tp (tp_ini.cpp): every linear axis at most that (0: not set).
    for (int i = 0; i < m.limits.axes; ++i) {
        double& jerk = m.limits.axis[i].max_jerk;
        const double given = ini_axis_jerk(axis_letters[i], own_jerk[i] ? jerk : 0.0, linear_jerk);
        if (own_jerk[i] || given > 0.0) jerk = given;
    }
}

// What LinuxCNC's interpreter reads beside the INI; LINEAR_UNITS as LinuxCNC spells mm.
void read_interpreter_files(const IniFile& ini, MachineConfig& m) {
    if (const IniFile::Entry* e = ini.find("TRAJ", "LINEAR_UNITS");
        e != nullptr && e->value != "mm" && e->value != "metric" && e->value != "1.0" && e->value != "1")
        fail(ini, *e, cat("'", e->value, "': firtp plans in mm (LINEAR_UNITS = mm); programs may still use G20"));
    if (const IniFile::Entry* e = ini.find("RS274NGC", "RS274NGC_STARTUP_CODE")) m.startup_code = e->value;
    std::error_code ec;
    const std::filesystem::path ini_path(ini.file_name());
    if (!std::filesystem::is_regular_file(ini_path, ec)) return;  // parsed from text
    m.ini_file = std::filesystem::absolute(ini_path, ec);
    const auto beside = [&](std::string_view section, std::string_view key) -> std::filesystem::path {
        const IniFile::Entry* e = ini.find(section, key);
        if (e == nullptr || e->value.empty()) return {};
        return m.ini_file.parent_path() / e->value;
    };
    m.parameter_file = beside("RS274NGC", "PARAMETER_FILE");
    m.tool_table = beside("EMCIO", "TOOL_TABLE");
}

void read_firtp(const IniFile& ini, MachineConfig& m) {
    static constexpr std::string_view known[] = {"STAGES",    "T1", "T2", "T3", "T4", "MODES",
                                                 "TOLERANCE", "TOLERANCE_MEANING", "ARC_CHORD_TOLERANCE",
                                                 "RATE_RESERVE", "ROBUST", "MAX_PROGRAM_BLOCKS"};
    for (const IniFile::Entry* e : ini.section("FIRTP"))
        if (std::find(std::begin(known), std::end(known), e->key) == std::end(known))
            fail(ini, *e,
                 "unknown key (known: STAGES, T1..T4, MODES, TOLERANCE, TOLERANCE_MEANING, ARC_CHORD_TOLERANCE, "
                 "RATE_RESERVE, ROBUST, MAX_PROGRAM_BLOCKS)");
    if (const auto r = positive(ini, "FIRTP", "RATE_RESERVE")) {
        if (*r >= 1.0) fail(ini, *ini.find("FIRTP", "RATE_RESERVE"), "must be below 1 (a share of the acceleration and jerk limits)");
        m.rate_reserve = *r;
    }
    if (const auto o = positive(ini, "DISPLAY", "MAX_FEED_OVERRIDE")) {
        if (*o < 1.0) fail(ini, *ini.find("DISPLAY", "MAX_FEED_OVERRIDE"), "must be at least 1 (100 %)");
        m.max_feed_override = *o;
    }

    if (const auto stages = whole(ini, "FIRTP", "STAGES", 1, max_stages, "1 to 4")) m.stages = static_cast<int>(*stages);
    for (std::size_t i = 0; i < max_stages; ++i) {
        const auto t = positive(ini, "FIRTP", cat("T", std::to_string(i + 1)));
        if (!t) continue;
        if (m.given_times.size() <= i) m.given_times.resize(i + 1, 0.0);
        m.given_times[i] = *t;
    }
    parse_key(ini, "FIRTP", "MODES", [&](const std::string& text) { m.tuning.modes = parse_modes(text, m.limits.axes); });
    parse_key(ini, "FIRTP", "ROBUST", [&](const std::string& text) { parse_robust(text, m.tuning); });
    if (const auto blocks = whole(ini, "FIRTP", "MAX_PROGRAM_BLOCKS", 1, 1e15, "1 to 1e15"))  // 1e15: exact in a double
        m.max_program_blocks = static_cast<std::size_t>(*blocks);
    if (const auto tol = positive(ini, "FIRTP", "TOLERANCE")) m.default_tolerance = *tol;
    if (const auto chord = positive(ini, "FIRTP", "ARC_CHORD_TOLERANCE")) m.arc_chord_tolerance = *chord;
    if (const IniFile::Entry* e = ini.find("FIRTP", "TOLERANCE_MEANING")) {
        std::string v = e->value;
        std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        const std::optional<ToleranceMeaning> meaning = parse_tolerance_meaning(v);
        if (!meaning) fail(ini, *e, cat("'", e->value, "' must be corner or contour"));
        m.tolerance_meaning = *meaning;
    }
}

std::string short_number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// The machine's filter times, checked at load so that impossible ones are refused naming the key
// they come from: a stage that is neither given nor derivable, modes that cannot be tuned, and a
// filter window longer than the planner is built for (validate_window: a jerk limit of 1 gives
// T2 = a / j = 5000 s, whose window would take gigabytes).
void check_filters(const IniFile& ini, const MachineConfig& m) {
    const IniFile::Entry* modes = ini.find("FIRTP", "MODES");
    const IniFile::Entry* stages = ini.find("FIRTP", "STAGES");
    const auto at_file = [&](const std::string& text) { throw ConfigError(cat(ini.file_name(), ":0: ", text)); };
    const std::array<double, max_stages> t = limit_filter_times(m.limits, m.given_times);  // untuned, by position
    const bool tuned = !m.tuning.modes.empty();

    // Refuses a delay longer than the window, naming the key the longest stage comes from.
    const auto refuse_window = [&](double delay, const char* is, bool blame_modes) {
        const std::string text = cat("the filter delay T1 + ... + Tn ", is, " ", short_number(delay), " s is ",
                                     short_number(std::round(delay / m.period)), " servo periods (at most ",
                                     short_number(max_window_periods), ")");
        const IniFile::Entry* period = ini.find("EMCMOT", "SERVO_PERIOD");
        if (period && delay <= max_window_periods * 0.001) fail(ini, *period, cat(text, ": the servo period is too short"));
        if (blame_modes && modes) fail(ini, *modes, text);  // the tuning made it this long
        std::size_t longest = 0;  // the longest stage, given or derived from an axis' limits
        for (std::size_t i = 1; i < static_cast<std::size_t>(tuned ? max_stages : m.stages); ++i)
            if (t[i] > t[longest]) longest = i;
        const std::string stage = cat("T", std::to_string(longest + 1));
        if (longest < m.given_times.size() && m.given_times[longest] > 0.0) fail(ini, *ini.find("FIRTP", stage), text);
        const bool velocity_over_acceleration = longest == 0;  // T1 = v / a, T2 = a / j
        double AxisLimits::*num = velocity_over_acceleration ? &AxisLimits::max_velocity : &AxisLimits::max_acceleration;
        double AxisLimits::*den = velocity_over_acceleration ? &AxisLimits::max_acceleration : &AxisLimits::max_jerk;
        for (int a = 0; a < m.limits.axes && t[longest] > 0.0; ++a) {
            const AxisLimits& l = m.limits.axis[a];
            if (!(l.*num > 0.0 && l.*den > 0.0 && l.*num / l.*den == t[longest])) continue;
            const std::string section = std::string("AXIS_") + axis_letters[a];
            const char* den_key = velocity_over_acceleration ? "MAX_ACCELERATION" : "MAX_JERK";
            const char* num_key = velocity_over_acceleration ? "MAX_VELOCITY" : "MAX_ACCELERATION";
            const std::string why = cat(text, ": ", stage, " = ", num_key, " / ", den_key, " = ", short_number(t[longest]), " s");
            if (const IniFile::Entry* e = ini.find(section, den_key)) fail(ini, *e, why);
            if (const IniFile::Entry* e = ini.find(section, num_key)) fail(ini, *e, why);
            at_file(cat("[", section, "]", den_key, ": ", why));
        }
        if (modes) fail(ini, *modes, text);
        at_file(text);
    };

    if (tuned) {  // before tuning: its stage times are whole numbers of mode periods above these bounds
        const double bound = *std::max_element(t.begin(), t.end());
        if (!(bound <= max_window_periods * m.period)) refuse_window(bound, "is at least", false);
        for (const StructuralMode& mode : m.tuning.modes)  // straddled zeros sit up to 1.5 f
            if (!(mode.frequency_hz * 1.5 * bound <= 1e6))
                fail(ini, *modes, cat(short_number(mode.frequency_hz), " Hz: a filter stage of ", short_number(bound),
                                      " s would span more than a million periods of this mode"));
    }
    FilterTimes f;
    try {
        f = m.filter_times();
    } catch (const ConfigError& e) {
        if (modes) fail(ini, *modes, e.what());
        if (stages) fail(ini, *stages, e.what());
        at_file(e.what());
    }
    if (*validate_window(f, m.period) != '\0') refuse_window(f.delay(), "=", tuned);
}

// Smoothing at the limits needs an acceleration limit for every axis (T1 of a move = its speed
// change over the acceleration of its most loaded axis).
// Limit-driven smoothing needs each axis' acceleration limit. An axis without an [AXIS_] section
// is one the machine does not have: a move of it is refused when planned.
void check_accelerations(const IniFile& ini, const MachineConfig& m) {
    std::array<bool, max_axes> named{};
    if (const IniFile::Entry* e = coordinates(ini, named))
        for (int a = 0; a < max_axes; ++a)
            if (named[static_cast<std::size_t>(a)] && !(m.limits.axis[a].max_acceleration > 0.0))
                fail(ini, *e, cat("names ", std::string(1, axis_letters[a]), " but [AXIS_", std::string(1, axis_letters[a]),
                                  "] gives no MAX_ACCELERATION"));
    bool any = false;
    for (int a = 0; a < m.limits.axes; ++a) {
        const std::string section = std::string("AXIS_") + axis_letters[a];
        const bool given = m.limits.axis[a].max_acceleration > 0.0;
        any = any || given;
        if (given || ini.section(section).empty()) continue;
        throw ConfigError(cat(ini.file_name(), ":", std::to_string(ini.section(section).front()->line), ": [", section,
                              "]MAX_ACCELERATION is missing: moves are smoothed at each axis' acceleration limit "
                              "(or give [FIRTP]T1 for the paper's fixed chain)"));
    }
    if (!any)
        throw ConfigError(cat(ini.file_name(), ":0: no axis has a MAX_ACCELERATION: moves are smoothed at each axis' "
                              "acceleration limit (or give [FIRTP]T1 for the paper's fixed chain)"));
}

void check_override(const std::optional<double>& value, const char* flag, const char* what) {
    if (value && !(std::isfinite(*value) && *value > 0.0))
        throw ConfigError(cat(flag, ": must be a positive ", what));
}

}  // namespace

bool MachineConfig::fixed_chain() const {
    return !tuning.modes.empty() || std::any_of(given_times.begin(), given_times.end(), [](double t) { return t > 0.0; });
}

FilterTimes MachineConfig::filter_times() const {
    if (!tuning.modes.empty()) return tuned_filters().filters;
    try {
        return filter_times_from_limits(limits, stages, given_times, {});
    } catch (const std::invalid_argument& e) {
        throw ConfigError(cat("filter times: ", e.what()));
    }
}

TunedFilters MachineConfig::tuned_filters() const {
    try {
        if (tuning.modes.empty()) {
            TunedFilters untuned;
            untuned.filters = filter_times_from_limits(limits, stages, given_times, {});
            for (int i = 0; i < untuned.filters.stages; ++i)
                untuned.stages[i].time = untuned.filters.T[i];
            return untuned;
        }
        return tune_filter_times(limits, stages, given_times, tuning);
    } catch (const std::invalid_argument& e) {
        throw ConfigError(cat("filter times: ", e.what()));
    }
}

PlannerParameters MachineConfig::planner_parameters() const {
    PlannerParameters p;
    p.fixed_chain = fixed_chain();
    if (p.fixed_chain) p.filters = filter_times();
    else if (std::none_of(limits.axis.begin(), limits.axis.begin() + limits.axes,
                          [](const AxisLimits& l) { return l.max_acceleration > 0.0; }))
        throw ConfigError("no axis has an acceleration limit (MAX_ACCELERATION): moves are smoothed at the limits "
                          "(or give T1 for the paper's fixed chain)");
    p.period = period;
    p.tolerance_meaning = tolerance_meaning;
    p.limits = limits;
    p.max_rate = max_feed_override;
    p.rate_reserve = rate_reserve;
    return p;
}

MachineConfig default_machine() {
    MachineConfig m;  // the period, stages, tolerance and arc chords as MachineConfig's defaults
    m.limits.axes = 3;
    m.limits.max_linear_velocity = 0.0;
    for (std::size_t i = 0; i < 3; ++i) m.limits.axis[i] = AxisLimits{300.0, 5000.0, 100000.0};
    return m;
}

MachineConfig load_machine(const IniFile& ini) {
    MachineConfig m = default_machine();
    read_interpreter_files(ini, m);
    read_period(ini, m);
    read_axes(ini, m);
    read_firtp(ini, m);
    if (m.fixed_chain()) check_filters(ini, m);
    else check_accelerations(ini, m);
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

namespace {

// A number that fills the whole word, or nullopt.
std::optional<double> whole_number(std::string_view word) {
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc{} || ptr != word.data() + word.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::vector<std::string> words_of(std::string_view text) {
    std::string spaced(text);
    std::replace(spaced.begin(), spaced.end(), ',', ' ');
    std::istringstream in(spaced);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

StructuralMode parse_mode(const std::string& word, int axes) {
    StructuralMode mode;
    std::string_view rest = word;
    if (const std::size_t colon = rest.find(':'); colon != std::string_view::npos) {
        const std::string_view letter = rest.substr(0, colon);
        const auto* found = letter.size() == 1
                                ? std::find(axis_letters.begin(), axis_letters.end(),
                                            static_cast<char>(std::toupper(static_cast<unsigned char>(letter[0]))))
                                : axis_letters.end();
        if (found == axis_letters.end() || found - axis_letters.begin() >= axes)
            throw ConfigError(cat("'", word, "': '", std::string(letter), "' is not an axis of this machine"));
        mode.axis = static_cast<int>(found - axis_letters.begin());
        rest = rest.substr(colon + 1);
    }
    const std::size_t slash = rest.find('/');
    const auto hz = whole_number(rest.substr(0, slash));
    if (!hz) throw ConfigError(cat("'", word, "' is not a number"));
    if (*hz <= 0.0) throw ConfigError(cat("'", word, "' must be a positive frequency in Hz"));
    mode.frequency_hz = *hz;
    if (slash != std::string_view::npos) {
        const auto zeta = whole_number(rest.substr(slash + 1));
        if (!zeta) throw ConfigError(cat("'", word, "': the damping is not a number"));
        if (*zeta < 0.0 || *zeta >= 1.0) throw ConfigError(cat("'", word, "': the damping must lie in [0, 1)"));
        mode.damping = *zeta;
    }
    return mode;
}

}  // namespace

std::vector<StructuralMode> parse_modes(std::string_view text, int axes) {
    std::vector<StructuralMode> modes;
    for (const std::string& word : words_of(text)) modes.push_back(parse_mode(word, axes));
    return modes;
}

void parse_robust(std::string_view text, ModeTuning& tuning) {
    std::string spaced(text);
    std::replace(spaced.begin(), spaced.end(), ':', ' ');
    const std::vector<std::string> words = words_of(spaced);
    std::string name = words.empty() ? "" : words[0];
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const auto usage = [&] {
        return ConfigError(cat("'", std::string(text), "' must be none, double, straddle or straddle SPREAD (0 < SPREAD < 0.5)"));
    };
    tuning.spread = 0.0;
    if (name == "none" && words.size() == 1) tuning.robust = RobustTuning::none;
    else if (name == "double" && words.size() == 1) tuning.robust = RobustTuning::double_stage;
    else if (name == "straddle" && words.size() <= 2) {
        tuning.robust = RobustTuning::straddle;
        if (words.size() == 2) {
            const auto spread = whole_number(words[1]);
            if (!spread || *spread <= 0.0 || *spread >= 0.5) throw usage();
            tuning.spread = *spread;
        }
    } else {
        throw usage();
    }
}

}  // namespace firtp
