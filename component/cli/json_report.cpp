#include "json_report.hpp"

#include <firtp/kernel.hpp>

#include <cmath>
#include <numbers>

namespace firtp::cli {
namespace {

using nlohmann::json;

json xyz(const AxisVector& v) { return json::array({v[0], v[1], v[2]}); }

json finite_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json machine_json(const PlanRun& run) {
    json machine = {{"smoothing", run.parameters.fixed_chain ? "fixed_chain" : "limits"},
                    {"period_s", run.parameters.period},
                    {"default_tolerance_mm", run.machine.default_tolerance},
                    {"tolerance_meaning", to_string(run.parameters.tolerance_meaning)}};
    if (run.parameters.fixed_chain) {  // the paper's chain
        const FilterTimes& f = run.parameters.filters;
        json times = json::array();
        for (int i = 0; i < f.stages; ++i) times.push_back(f.T[i]);
        machine["stages"] = f.stages;
        machine["T_s"] = times;
        machine["delay_s"] = f.delay();
    } else {
        machine["jerk_time_s"] = jerk_time(smoothing_limits(run.parameters.limits));
    }
    return machine;
}

json axis_name(int axis) {
    return axis >= 0 ? json(std::string(1, axis_letters[axis])) : json(nullptr);
}

json corner_json(const PlanRun& run, std::size_t i) {
    const CornerReport& c = run.corners[i];
    const auto& measured = run.corners.error(i);
    json corner = {{"line", c.line},
                   {"point", xyz(c.point)},
                   {"beta_deg", c.beta * 180.0 / std::numbers::pi},
                   {"speed_in_mm_s", c.speed_in},
                   {"speed_out_mm_s", c.speed_out},
                   {"bound", describe(c.bound)},
                   {"bound_axis", axis_name(c.axis)},
                   {"epsilon_mm", finite_or_null(c.epsilon)},
                   {"predicted_error_mm", c.predicted_error},
                   {"measured_error_mm", measured ? json(*measured) : json(nullptr)},
                   {"exact_stop", c.exact_stop}};
    if (run.parameters.fixed_chain) {
        corner["tk_s"] = c.Tk;
        corner["tk_tolerance_s"] = c.Tk_tolerance;
    }
    return corner;
}

json corners_json(const PlanRun& run) {
    json corners = json::array();
    for (std::size_t i = 0; i < run.corners.size(); ++i) corners.push_back(corner_json(run, i));
    return corners;
}

json measured_json(const PlanRun& run) {
    const Measured& m = run.measured;
    return {{"max_corner_error_mm", m.max_corner_error},
            {"max_contour_error_mm", m.max_contour_error},
            {"max_path_speed_mm_s", m.max_path_speed},
            {"max_axis_velocity", xyz(m.max_velocity)},
            {"max_axis_acceleration", xyz(m.max_acceleration)},
            {"max_axis_jerk", xyz(m.max_jerk)},
            {"end_position", xyz(m.end_position)},
            {"end_error_mm", (m.end_position - run.points.back()).norm()},
            {"finite", m.finite}};
}

// Non-motion words in program order: where (file:line) and between which blocks.
json events_json(const Program& program) {
    json events = json::array();
    for (const ProgramEvent& e : program.events)
        events.push_back({{"kind", std::string(event_name(e.kind))}, {"value", e.value}, {"file", e.file},
                          {"line", e.line}, {"before_block", e.before_block}, {"motion_waits", event_waits(e.kind)}});
    return events;
}

}  // namespace

nlohmann::json json_report(const PlanRun& run, const std::string& program_name, bool with_corners) {
    return {{"program", program_name},
            {"machine", machine_json(run)},
            {"blocks", run.points.size() - 1},
            {"cycle_time_s", run.trajectory.cycle_time},
            {"closed_form_cycle_time_s", run.parameters.fixed_chain ? json(run.closed_form_cycle_time) : json(nullptr)},
            {"feed_time_s", run.feed_time},
            {"naive_cam", {{"joined_moves", run.program.joined.moves}, {"farthest_mm", run.program.joined.farthest}}},
            {"corners", with_corners ? corners_json(run) : json::array()},
            {"events", events_json(run.program)},
            {"measured", measured_json(run)}};
}

void write_json_report(std::ostream& out, const PlanRun& run, const std::string& program_name) {
    const std::string text = json_report(run, program_name, false).dump(2);
    const std::string empty = "\"corners\": []";
    const std::size_t at = text.find(empty);
    if (at == std::string::npos || run.corners.empty()) {
        out << text << "\n";
        return;
    }
    // Each corner as dump(2) writes it two levels down: every line indented by four spaces.
    out << text.substr(0, at) << "\"corners\": [\n";
    for (std::size_t i = 0; i < run.corners.size(); ++i) {
        const std::string corner = corner_json(run, i).dump(2);
        std::string indented = i ? ",\n    " : "    ";
        for (char ch : corner) {
            indented += ch;
            if (ch == '\n') indented += "    ";
        }
        out << indented;
    }
    out << "\n  ]" << text.substr(at + empty.size()) << "\n";
}

}  // namespace firtp::cli
