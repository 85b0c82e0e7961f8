#include "checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace firtp::tp_check {
namespace {

using Failures = std::vector<std::string>;

template <class... Args>
std::string text(const char* format, Args... args) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, args...);
    return buffer;
}

void check_end(const Options& o, const Measurement& m, Failures& fail) {
    if (o.stopped) {
        const std::vector<Row>& rows = m.recording.rows;
        const std::size_t n = rows.size();
        if (n < 20 || rows[n - 1].position != rows[n - 20].position) fail.push_back("the tool did not come to rest");
        if (m.end_error < 1e-6) fail.push_back("the tool reached the program's end: nothing was stopped");
    } else if (m.end_error > 1e-9) {
        fail.push_back(text("the tool ends %.6g mm from the program's end", m.end_error));
    }
}

void check_tolerances(const Options& o, const Measured& m, Failures& fail) {
    if (o.tolerance >= 0.0 && m.max_contour_error > o.tolerance * (1 + 1e-9))
        fail.push_back(text("contour error %.6f mm > tolerance %.6f mm", m.max_contour_error, o.tolerance));
    if (o.corner_tolerance >= 0.0 && m.max_corner_error > o.corner_tolerance * (1 + 1e-9))
        fail.push_back(text("corner error %.6f mm > tolerance %.6f mm", m.max_corner_error, o.corner_tolerance));
}

void check_axes(const Options& o, const MachineConfig& machine, const Measured& m, Failures& fail) {
    for (int a = 0; a < 3; ++a) {
        const AxisLimits& l = machine.limits.axis[a];
        const char axis = axis_letters[a];
        if (o.limits && l.max_velocity > 0.0 && m.max_velocity[a] > l.max_velocity * (1 + 1e-9))
            fail.push_back(text("%c velocity %.3f > MAX_VELOCITY %.3f", axis, m.max_velocity[a], l.max_velocity));
        if (o.limits && l.max_acceleration > 0.0 && m.max_acceleration[a] > l.max_acceleration * (1 + 1e-6))
            fail.push_back(text("%c acceleration %.1f > MAX_ACCELERATION %.1f", axis, m.max_acceleration[a],
                                l.max_acceleration));
        if (o.jerk > 0.0 && m.max_jerk[a] > o.jerk * (1 + 1e-6))
            fail.push_back(text("%c jerk %.0f > %.0f", axis, m.max_jerk[a], o.jerk));
    }
}

void check_timing(const Options& o, const Measurement& m, Failures& fail) {
    if (o.hold > 0.0 && m.longest_rest < o.hold)
        fail.push_back(text("the tool rested at most %.3f s inside the motion, expected %.3f s", m.longest_rest, o.hold));
    if (o.cycle_time > 0.0 && std::abs(m.measured.cycle_time - o.cycle_time) > o.cycle_within)
        fail.push_back(text("cycle time %.4f s, expected %.4f +- %.4f s", m.measured.cycle_time, o.cycle_time,
                            o.cycle_within));
}

void check_lines(const Options& o, const std::vector<long>& lines, Failures& fail) {
    if (o.expected_lines.empty() || lines == o.expected_lines) return;
    std::string seen;
    for (long l : lines) {
        if (!seen.empty()) seen += ',';
        seen += std::to_string(l);
    }
    fail.push_back("program lines while moving were " + seen);
}

// firtp plan's CSV: t,x,y,z,... one row a period from rest at the start to rest at the end.
void check_reference(const Options& o, const Measurement& m, nlohmann::json& report, Failures& fail) {
    const std::vector<AxisVector> plan = read_reference(o.reference_path);
    double largest = 0.0;
    const std::size_t n = std::min(plan.size(), m.samples.size());
    for (std::size_t k = 0; k < n; ++k) largest = std::max(largest, (m.samples[k].position - plan[k]).norm());
    report["reference_periods"] = plan.size();
    report["largest_difference_from_reference_mm"] = largest;
    std::printf("reference    %zu periods planned offline, %zu recorded; largest difference %.3g mm\n", plan.size(),
                m.samples.size(), largest);
    if (plan.size() != m.samples.size())
        fail.push_back(text("%zu periods recorded, %zu in %s", m.samples.size(), plan.size(), o.reference_path.c_str()));
    if (!(largest <= o.within))
        fail.push_back(text("differs from the offline plan by %.3g mm (allowed %.3g)", largest, o.within));
}

}  // namespace

Failures check_motion(const Options& o, const MachineConfig& machine, const Measurement& m, nlohmann::json& report) {
    Failures fail;
    if (m.recording.overruns > 0)
        fail.push_back("the sampler lost samples (" + std::to_string(m.recording.overruns) + " overruns)");
    if (!m.measured.finite) fail.push_back("a sample is not finite");
    check_end(o, m, fail);
    check_tolerances(o, m.measured, fail);
    check_axes(o, machine, m.measured, fail);
    if (!o.reference_path.empty()) check_reference(o, m, report, fail);
    check_timing(o, m, fail);
    check_lines(o, m.lines, fail);
    return fail;
}

}  // namespace firtp::tp_check
