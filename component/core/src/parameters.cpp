#include <firtp/parameters.hpp>

#include <firtp/mode_tuning.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <functional>
#include <stdexcept>
#include <string>

namespace firtp {

std::optional<ToleranceMeaning> parse_tolerance_meaning(std::string_view word) {
    if (word == "corner") return ToleranceMeaning::corner_point;
    if (word == "contour") return ToleranceMeaning::contour;
    return std::nullopt;
}

const char* to_string(ToleranceMeaning meaning) {
    return meaning == ToleranceMeaning::contour ? "contour" : "corner";
}

double FilterTimes::delay() const {
    double td = 0.0;
    for (int i = 0; i < stages; ++i) td += T[i];
    return td;
}

const char* validate(const FilterTimes& filters) {
    if (filters.stages < 1 || filters.stages > max_stages) return "the chain needs 1 to 4 stages";
    for (int i = 0; i < filters.stages; ++i) {
        if (!std::isfinite(filters.T[i]) || filters.T[i] <= 0.0) return "filter times must be positive and finite";
        if (i > 0 && filters.T[i] > filters.T[i - 1]) return "filter times must not increase (T1 >= T2 >= ...)";
    }
    return "";
}

const char* validate_window(const FilterTimes& filters, double period) {
    if (!(std::isfinite(period) && period > 0.0)) return "the servo period must be positive and finite";
    static_assert(max_window_periods == 20000.0, "the text below names the bound");
    if (!(filters.delay() <= max_window_periods * period))
        return "the filter delay T1 + ... + Tn is longer than 20000 servo periods (20 s at 1 ms)";
    return "";
}

namespace {

// Largest ratio over the axes in use, 0 when no axis has both values.
double worst_ratio(const MachineLimits& limits, double AxisLimits::*num, double AxisLimits::*den) {
    double worst = 0.0;
    for (int a = 0; a < limits.axes; ++a) {
        const AxisLimits& l = limits.axis[a];
        if (l.*num > 0.0 && l.*den > 0.0) worst = std::max(worst, l.*num / l.*den);
    }
    return worst;
}

}  // namespace

std::array<double, max_stages> limit_filter_times(const MachineLimits& limits, std::span<const double> given) {
    std::array<double, max_stages> t{};
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = i < given.size() ? given[i] : 0.0;
    if (t[0] <= 0.0) t[0] = worst_ratio(limits, &AxisLimits::max_velocity, &AxisLimits::max_acceleration);
    if (t[1] <= 0.0) t[1] = jerk_time(limits);
    return t;
}

FilterTimes filter_times_from_limits(const MachineLimits& limits, int stages,
                                     std::span<const double> given,
                                     std::span<const double> mode_frequencies_hz) {
    if (stages < 1 || stages > max_stages) throw std::invalid_argument("the chain needs 1 to 4 stages");
    if (!mode_frequencies_hz.empty()) {
        ModeTuning tuning;
        for (double hz : mode_frequencies_hz) tuning.modes.push_back({hz, default_mode_damping, -1});
        return tune_filter_times(limits, stages, given, tuning).filters;
    }
    const std::array<double, max_stages> times = limit_filter_times(limits, given);
    FilterTimes f;
    f.stages = stages;
    for (int i = 0; i < stages; ++i) {
        const double t = times[i];
        if (!(t > 0.0) || !std::isfinite(t))
            throw std::invalid_argument("T" + std::to_string(i + 1) +
                                        " is neither given nor derivable from the axis limits or a mode");
        f.T[i] = t;
    }
    std::sort(f.T.begin(), f.T.begin() + stages, std::greater<>());
    return f;
}

MachineLimits planned_limits(const PlannerParameters& parameters) {
    if (!parameters.fixed_chain) return parameters.limits;  // the override is planned, not scaled
    const double m = std::max(parameters.max_rate, 1.0), keep = 1.0 - parameters.rate_reserve;
    MachineLimits planned = parameters.limits;
    for (AxisLimits& l : planned.axis) {
        l.max_velocity /= m;
        l.max_acceleration *= keep / (m * m);
        l.max_jerk *= keep / (m * m * m);
    }
    planned.max_linear_velocity /= m;
    return planned;
}

double ini_axis_jerk(char letter, double own, double linear) {
    if (letter == 'A' || letter == 'B' || letter == 'C' || !(linear > 0.0)) return own > 0.0 ? own : 0.0;
    return own > 0.0 ? std::min(own, linear) : linear;
}

double jerk_time(const MachineLimits& limits) {
    return worst_ratio(limits, &AxisLimits::max_acceleration, &AxisLimits::max_jerk);
}

MachineLimits smoothing_limits(const MachineLimits& limits) {
    double t2 = 0.0;
    for (int a = 0; a < limits.axes; ++a) {
        const AxisLimits& l = limits.axis[a];
        if (!(l.max_acceleration > 0.0 && l.max_jerk > 0.0)) continue;
        double t = l.max_acceleration / l.max_jerk;
        if (l.max_velocity > 0.0) t = std::min(t, std::sqrt(2.0 * l.max_velocity / l.max_jerk));
        t2 = std::max(t2, t);
    }
    MachineLimits planned = limits;
    for (int a = 0; a < limits.axes; ++a) {
        AxisLimits& l = planned.axis[a];
        if (l.max_jerk > 0.0) l.max_acceleration = std::min(l.max_acceleration, l.max_jerk * t2);
    }
    return planned;
}

double hold_time_bound(const PlannerParameters& parameters) {
    const MachineLimits planned = smoothing_limits(parameters.limits);
    const double ramp = worst_ratio(planned, &AxisLimits::max_velocity, &AxisLimits::max_acceleration);
    return 2.0 * (ramp + 2.0 * jerk_time(planned));
}

double arc_speed_limit(const FilterTimes& filters, double radius, double tolerance) {
    constexpr double shrink_share = 0.9;
    double squares = 0.0;
    for (int i = 0; i < filters.stages; ++i) squares += filters.T[i] * filters.T[i];
    if (!(squares > 0.0) || !(radius > 0.0) || !std::isfinite(tolerance) || !(tolerance > 0.0))
        return std::numeric_limits<double>::infinity();
    return std::sqrt(24.0 * radius * shrink_share * tolerance / squares);
}

const char* validate_rate(const PlannerParameters& parameters) {
    if (!(std::isfinite(parameters.max_rate) && parameters.max_rate >= 1.0))
        return "the highest feed override must be at least 1 (100 %)";
    if (!(parameters.rate_reserve > 0.0 && parameters.rate_reserve < 1.0))
        return "the rate reserve must lie between 0 and 1 (a share of the acceleration and jerk limits)";
    return "";
}

}  // namespace firtp
