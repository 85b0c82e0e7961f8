#include "vibration_table.hpp"

#include "number_text.hpp"

#include <firtp/text_cat.hpp>

#include <cstdio>
#include <sstream>

namespace firtp::cli {
namespace {

using nlohmann::json;

constexpr std::size_t untuned_case = 1;  // VibrationStudy::cases order: tuned, untuned, S-curve

std::string percent(double value, double reference) {
    if (!(reference > 0.0)) return "-";
    return cat(fixed_text(100.0 * value / reference, 1), " %");
}

std::string mm(double value) { return cat(fixed_text(value, 6), " mm"); }

std::string letter(int axis) { return std::string(1, axis_letters[axis]); }

std::string stage_roles(const VibrationStudy& s) {
    std::string text;
    for (int i = 0; i < s.tuned.filters.stages; ++i) {
        const TunedStage& st = s.tuned.stages[i];
        text += i ? ", " : "";
        text += fixed_text(st.time * 1e3, 3) + " ms ";
        if (st.mode < 0) text += "for the limits";
        else
            text += cat("on ", fixed_text(st.zero_hz, 2), " Hz (", fixed_text(s.tuned.modes[st.mode].frequency_hz, 2),
                        " Hz mode, k ", std::to_string(st.k), ")");
    }
    return text;
}

std::string modes_text(const VibrationStudy& s) {
    std::string text;
    for (std::size_t i = 0; i < s.plant.size(); ++i) {
        const PlantMode& p = s.plant[i];
        text += cat(i ? ", " : "", letter(p.axis), " ", fixed_text(p.tuned_hz, 2), " Hz (damping ", fixed_text(p.damping, 3), ")");
    }
    if (s.detune != 0.0)
        text += cat("; the machine's modes are ", s.detune > 0 ? "+" : "", fixed_text(100.0 * s.detune, 1),
                    " % off them");
    return text;
}

std::string cost_text(const VibrationStudy& s) {
    const PlannerCase& tuned = s.cases[0];
    const PlannerCase& untuned = s.cases[untuned_case];
    return cat("Td ", fixed_text(tuned.delay * 1e3, 3), " ms vs ", fixed_text(untuned.delay * 1e3, 3),
               " ms untuned (", tuned.delay >= untuned.delay ? "+" : "", fixed_text((tuned.delay - untuned.delay) * 1e3, 3),
               " ms a stop); cycle time ", fixed_text(tuned.cycle_time, 4), " s vs ", fixed_text(untuned.cycle_time, 4),
               " s (", tuned.cycle_time >= untuned.cycle_time ? "+" : "",
               percent(tuned.cycle_time - untuned.cycle_time, untuned.cycle_time), "), S-curve ",
               fixed_text(s.cases[2].cycle_time, 4), " s");
}

std::string pad(const std::string& text, std::size_t width, bool right = false) {
    if (text.size() >= width) return text;
    const std::string fill(width - text.size(), ' ');
    return right ? fill + text : text + fill;
}

}  // namespace

std::string band_text(const FrequencyBand& band) {
    if (band.empty) return "none";
    const std::string high = band.open_above ? "beyond +100 %" : cat("+", fixed_text(100.0 * band.high, 1), " %");
    return cat(fixed_text(100.0 * band.low, 1), " % ... ", high);
}

void print_vibration(std::ostream& out, const VibrationStudy& s) {
    out << "program      " << s.program << "\n"
        << "modes        " << modes_text(s) << "\n"
        << "tuned        " << s.cases[0].filters << ": " << stage_roles(s) << "\n"
        << "untuned      " << s.cases[untuned_case].filters << ", " << s.untuned_note << "\n"
        << "reference    " << s.cases[2].filters << ", limits as firtp plans them\n\n";
    out << pad("mode", 13) << pad("planner", 22) << pad("cycle time", 11, true) << pad("stops", 7, true)
        << pad("residual after stops", 27, true) << pad("vibration moving", 25, true) << pad("lag moving", 14, true)
        << "\n";
    for (std::size_t m = 0; m < s.plant.size(); ++m) {
        const ModeResponse& ref = s.cases[untuned_case].responses[m];
        for (std::size_t c = 0; c < s.cases.size(); ++c) {
            const PlannerCase& pc = s.cases[c];
            const ModeResponse& r = pc.responses[m];
            out << pad(c == 0 ? plant_name(s.plant[m]) : "", 13) << pad(pc.name, 22)
                << pad(fixed_text(pc.cycle_time, 4) + " s", 11, true) << pad(std::to_string(r.stops.size()), 7, true)
                << pad(mm(r.max_stop_residual), 18, true) << pad(percent(r.max_stop_residual, ref.max_stop_residual), 9, true)
                << pad(mm(r.max_moving_vibration), 16, true)
                << pad(percent(r.max_moving_vibration, ref.max_moving_vibration), 9, true)
                << pad(mm(r.max_moving_deflection), 14, true) << "\n";
        }
    }
    out << "\nbands        true frequencies over which the tuned chain keeps the residual within 5 % of the\n"
           "             untuned chain's (and of an unfiltered step's):\n";
    for (std::size_t m = 0; m < s.plant.size(); ++m)
        out << "             " << letter(s.plant[m].axis) << " " << fixed_text(s.plant[m].tuned_hz, 2)
            << " Hz: " << band_text(s.bands[m].vs_untuned) << " (" << band_text(s.bands[m].vs_unfiltered) << ")\n";
    out << "cost         " << cost_text(s) << "\n";
    out << "\nrobust       the options on this machine: delay, and per mode the band within 5 % of untuned\n";
    for (const RobustOption& o : s.options) {
        out << "             " << pad(o.name + " ", 22) << pad(cat("Td ", fixed_text(o.filters.delay() * 1e3, 1), " ms"), 14);
        for (std::size_t m = 0; m < s.plant.size(); ++m)
            out << (m ? "; " : "") << letter(s.plant[m].axis) << " " << band_text(o.bands[m].vs_untuned);
        out << "\n";
    }
}

std::string vibration_markdown(const VibrationStudy& s, const std::string& level) {
    std::ostringstream md;
    md << level << " Residual vibration\n\n"
       << "Modes: " << modes_text(s) << ".\n\n"
       << "| planner | filters | cycle time (s) |\n|---|---|---|\n";
    for (const PlannerCase& c : s.cases) md << "| " << c.name << " | " << c.filters << " | " << fixed_text(c.cycle_time, 4) << " |\n";
    md << "\nTuned stages: " << stage_roles(s) << ". Untuned: " << s.untuned_note << ".\n\n"
       << "Each mode is `x'' + 2 zeta w x' + w^2 x = -a(t)`, driven by its axis's planned acceleration. "
          "*Residual after stops*: the amplitude of the oscillation left when the machine comes to rest "
          "(largest over the stops). *Vibration moving*: the largest amplitude of the oscillation about the "
          "acceleration's own lag while moving (corners, ramps). *Lag moving*: the largest deflection |x| while "
          "moving. Shares are of firtp untuned.\n\n"
       << "| mode | planner | cycle time (s) | stops | residual after stops (mm) | share | vibration moving (mm) | share | lag moving (mm) |\n"
       << "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (std::size_t m = 0; m < s.plant.size(); ++m) {
        const ModeResponse& ref = s.cases[untuned_case].responses[m];
        for (const PlannerCase& c : s.cases) {
            const ModeResponse& r = c.responses[m];
            md << "| " << plant_name(s.plant[m]) << " | " << c.name << " | " << fixed_text(c.cycle_time, 4) << " | "
               << r.stops.size() << " | " << fixed_text(r.max_stop_residual, 6) << " | "
               << percent(r.max_stop_residual, ref.max_stop_residual) << " | " << fixed_text(r.max_moving_vibration, 6)
               << " | " << percent(r.max_moving_vibration, ref.max_moving_vibration) << " | "
               << fixed_text(r.max_moving_deflection, 6) << " |\n";
        }
    }
    md << "\nBands of frequency error over which the tuned chain keeps the residual vibration within 5 % of the "
          "untuned chain's, and of an unfiltered step's (input-shaper convention):\n\n"
       << "| mode | within 5 % of untuned | within 5 % of unfiltered |\n|---|---|---|\n";
    for (std::size_t m = 0; m < s.plant.size(); ++m)
        md << "| " << letter(s.plant[m].axis) << " " << fixed_text(s.plant[m].tuned_hz, 2) << " Hz | "
           << band_text(s.bands[m].vs_untuned) << " | " << band_text(s.bands[m].vs_unfiltered) << " |\n";
    md << "\nCost: " << cost_text(s) << ".\n";
    md << "\nThe robust options on this machine (`--robust` or `[FIRTP]ROBUST`): delay Td and, per mode, the band "
          "within 5 % of untuned (and of unfiltered):\n\n| option | Td (ms) |";
    for (const PlantMode& p : s.plant) md << " " << letter(p.axis) << " " << fixed_text(p.tuned_hz, 2) << " Hz |";
    md << "\n|---|---:|";
    for (std::size_t m = 0; m < s.plant.size(); ++m) md << "---|";
    md << "\n";
    for (const RobustOption& o : s.options) {
        md << "| " << o.name << " | " << fixed_text(o.filters.delay() * 1e3, 1) << " |";
        for (std::size_t m = 0; m < s.plant.size(); ++m)
            md << " " << band_text(o.bands[m].vs_untuned) << " (" << band_text(o.bands[m].vs_unfiltered) << ") |";
        md << "\n";
    }
    return md.str();
}

namespace {

json band_json(const FrequencyBand& b) {
    if (b.empty) return nullptr;
    return {{"low", b.low}, {"high", b.high}, {"open_above", b.open_above}};
}

json times_json(const FilterTimes& f) {
    json t = json::array();
    for (int i = 0; i < f.stages; ++i) t.push_back(f.T[i]);
    return t;
}

}  // namespace

json vibration_json(const VibrationStudy& s) {
    json plant = json::array();
    for (std::size_t m = 0; m < s.plant.size(); ++m) {
        const PlantMode& p = s.plant[m];
        plant.push_back({{"axis", letter(p.axis)},
                         {"tuned_hz", p.tuned_hz},
                         {"frequency_hz", p.frequency_hz},
                         {"damping", p.damping},
                         {"band_vs_untuned", band_json(s.bands[m].vs_untuned)},
                         {"band_vs_unfiltered", band_json(s.bands[m].vs_unfiltered)}});
    }
    json stages = json::array();
    for (int i = 0; i < s.tuned.filters.stages; ++i) {
        const TunedStage& st = s.tuned.stages[i];
        stages.push_back({{"T_s", st.time},
                          {"mode_hz", st.mode < 0 ? json(nullptr) : json(s.tuned.modes[st.mode].frequency_hz)},
                          {"zero_hz", st.mode < 0 ? json(nullptr) : json(st.zero_hz)},
                          {"k", st.k}});
    }
    json cases = json::array();
    for (const PlannerCase& c : s.cases) {
        json modes = json::array();
        for (std::size_t m = 0; m < s.plant.size(); ++m) {
            const ModeResponse& r = c.responses[m];
            json stops = json::array();
            for (const ModeResponse::Stop& st : r.stops) stops.push_back({{"time_s", st.time}, {"residual_mm", st.amplitude}});
            modes.push_back({{"axis", letter(s.plant[m].axis)},
                             {"frequency_hz", s.plant[m].frequency_hz},
                             {"max_stop_residual_mm", r.max_stop_residual},
                             {"max_moving_vibration_mm", r.max_moving_vibration},
                             {"max_moving_deflection_mm", r.max_moving_deflection},
                             {"stops", stops}});
        }
        cases.push_back({{"name", c.name}, {"delay_s", c.delay}, {"cycle_time_s", c.cycle_time}, {"modes", modes}});
    }
    json options = json::array();
    for (const RobustOption& o : s.options) {
        json bands = json::array();
        for (const ModeBands& b : o.bands)
            bands.push_back({{"band_vs_untuned", band_json(b.vs_untuned)}, {"band_vs_unfiltered", band_json(b.vs_unfiltered)}});
        options.push_back({{"name", o.name}, {"T_s", times_json(o.filters)}, {"delay_s", o.filters.delay()}, {"modes", bands}});
    }
    return {{"program", s.program},
            {"robust_options", options},
            {"period_s", s.period},
            {"detune", s.detune},
            {"tuned", {{"T_s", times_json(s.tuned.filters)}, {"delay_s", s.tuned.filters.delay()}, {"stages", stages}}},
            {"untuned", {{"T_s", times_json(s.untuned)}, {"delay_s", s.untuned.delay()}, {"note", s.untuned_note}}},
            {"modes", plant},
            {"cases", cases}};
}

}  // namespace firtp::cli
