#include "plan_checks.hpp"

#include "cli_errors.hpp"
#include "number_text.hpp"
#include <firtp/text_cat.hpp>

#include <cmath>
#include <ostream>
#include <string>

namespace firtp::cli {
namespace {

constexpr double rounding = 1e-6;  // relative: the differences of the samples round too

void check_axis(std::vector<std::string>& out, const char* what, const char* unit, const AxisVector& measured,
                const MachineLimits& limits, double AxisLimits::*limit) {
    for (int a = 0; a < limits.axes; ++a) {
        const double l = limits.axis[a].*limit;
        if (l > 0.0 && measured[a] > l * (1.0 + rounding))
            out.push_back(cat("axis ", std::string(1, axis_letters[a]), " ", what, " ", number_text(measured[a]),
                              " ", unit, " above its limit ", number_text(l)));
    }
}

}  // namespace

std::vector<std::string> measured_violations(const PlanRun& run) {
    std::vector<std::string> out;
    const Measured& m = run.measured;
    if (!m.finite) out.push_back("the samples are not all finite");
    if (run.parameters.tolerance_meaning == ToleranceMeaning::contour) {
        double widest = 0.0;  // the path within the largest tolerance at least
        bool bounded = false;
        for (const CornerReport& c : run.corners)
            if (std::isfinite(c.epsilon)) widest = std::max(widest, c.epsilon), bounded = true;
        if (bounded && m.max_contour_error > widest * (1.0 + rounding) + 1e-9)
            out.push_back(cat("contour error ", number_text(m.max_contour_error), " mm above the tolerance ", number_text(widest), " mm"));
    } else {
        for (std::size_t i = 0; i < run.corners.size(); ++i) {
            const CornerReport& c = run.corners[i];
            const auto& error = run.corners.error(i);
            if (error && std::isfinite(c.epsilon) && *error > c.epsilon * (1.0 + rounding) + 1e-9)
                out.push_back(cat("corner at line ", std::to_string(c.line), ": error ", number_text(*error),
                                  " mm above its tolerance ", number_text(c.epsilon), " mm"));
        }
    }
    const MachineLimits& limits = run.parameters.limits;
    check_axis(out, "velocity", "mm/s", m.max_velocity, limits, &AxisLimits::max_velocity);
    check_axis(out, "acceleration", "mm/s^2", m.max_acceleration, limits, &AxisLimits::max_acceleration);
    check_axis(out, "jerk", "mm/s^3", m.max_jerk, limits, &AxisLimits::max_jerk);
    if (!run.points.empty() && m.end_position != run.points.back())
        out.push_back(cat("the tool rests ", number_text((m.end_position - run.points.back()).norm()),
                          " mm from the program's end"));
    return out;
}

int report_violations(std::ostream& err, const PlanRun& run) {
    const std::vector<std::string> found = measured_violations(run);
    constexpr std::size_t shown = 10;
    for (std::size_t i = 0; i < found.size() && i < shown; ++i) err << "firtp: measured: " << found[i] << "\n";
    if (found.size() > shown) err << "firtp: measured: ... " << found.size() - shown << " more\n";
    return found.empty() ? 0 : exit_check_failed;
}

}  // namespace firtp::cli
