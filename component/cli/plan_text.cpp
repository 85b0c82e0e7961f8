#include "plan_text.hpp"

#include "number_text.hpp"

#include <firtp/kernel.hpp>
#include <firtp/text_cat.hpp>

#include <algorithm>

namespace firtp::cli {
namespace {

std::string ms(double seconds) { return fixed_text(seconds * 1e3, 3); }

}  // namespace

std::string machine_text(const PlanRun& run) {
    const PlannerParameters& p = run.parameters;
    std::string smoothing;
    if (p.fixed_chain) {
        std::string times;
        for (int i = 0; i < p.filters.stages; ++i) times += cat(i ? ", " : "", ms(p.filters.T[i]));
        smoothing = cat(std::to_string(p.filters.stages), " FIR stages, T = ", times, " ms (Td ", ms(p.filters.delay()), " ms)");
    } else {
        smoothing = cat("smoothing at the axis limits (jerk time T2 = ", ms(jerk_time(smoothing_limits(p.limits))), " ms)");
    }
    return cat(smoothing, ", period ", ms(p.period), " ms, tolerance bounds the ",
               p.tolerance_meaning == ToleranceMeaning::contour ? "contour" : "corner point");
}

std::string bound_text(const CornerReport& c) {
    std::string text = describe(c.bound);
    if ((c.bound == CornerBound::tolerance || c.bound == CornerBound::room) && c.axis >= 0)
        text += cat(", ", std::string(1, axis_letters[c.axis]), " at its acceleration limit");
    return text;
}

std::string reference_time_text(const PlanRun& run) {
    if (run.parameters.fixed_chain) return cat("closed form ", fixed_text(run.closed_form_cycle_time, 4), " s");
    return cat("at the programmed feed ", fixed_text(run.feed_time, 4), " s");
}

std::string slowest_junction_text(const PlanRun& run) {
    std::optional<CornerReport> slowest;
    for (const CornerReport& c : run.corners)
        if (!c.exact_stop && (!slowest || std::max(c.speed_in, c.speed_out) < std::max(slowest->speed_in, slowest->speed_out)))
            slowest = c;
    if (!slowest) return "none";
    return cat(fixed_text(std::max(slowest->speed_in, slowest->speed_out), 1), " mm/s at line ", std::to_string(slowest->line),
               " (", bound_text(*slowest), ")");
}

}  // namespace firtp::cli
