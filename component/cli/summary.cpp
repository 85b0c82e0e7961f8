#include "summary.hpp"

#include "number_text.hpp"
#include "plan_text.hpp"
#include <firtp/text_cat.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace firtp::cli {
namespace {

// The largest measured corner error, and the corners above their tolerance.
std::string corner_line(const PlanRun& run) {
    const auto& corners = run.corners;
    std::size_t worst = corners.size();
    std::size_t over = 0;
    double worst_error = -1.0;
    double worst_excess = 0.0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        if (!run.corners.error(i)) continue;
        const double error = *run.corners.error(i);
        if (error > worst_error) worst = i, worst_error = error;
        if (error > corners[i].epsilon) ++over, worst_excess = std::max(worst_excess, error - corners[i].epsilon);
    }
    if (worst == corners.size()) return "none measured";
    const CornerReport& c = corners[worst];
    std::string text = cat("max error ", fixed_text(worst_error, 4), " mm at line ", std::to_string(c.line),
                           " (tolerance ", std::isfinite(c.epsilon) ? cat(fixed_text(c.epsilon, 4), " mm)") : "none)");
    if (over == 0) return cat(text, "; all within tolerance");
    return cat(text, "; ", std::to_string(over), " of ", std::to_string(corners.size()),
               " above tolerance, by at most ", number_text(worst_excess), " mm");
}

std::string axis_max(const AxisVector& v, int decimals) {
    Eigen::Index axis = 0;
    const double value = v.head<3>().maxCoeff(&axis);
    return fixed_text(value, decimals) + " (" + axis_letters[axis] + ")";
}

// One line per kind of non-motion event, in the order of EventKind (the end, M2/M30, which every
// program has, only in the JSON).
void print_events(std::ostream& out, const Program& program, std::size_t blocks) {
    std::array<std::size_t, event_kinds> count{};
    double dwell = 0.0, after_last = 0.0;  // a dwell after the last move has no block to delay
    for (const ProgramEvent& e : program.events) {
        ++count[static_cast<std::size_t>(e.kind)];
        if (e.kind == EventKind::dwell) (e.before_block < blocks ? dwell : after_last) += e.value;
    }
    for (std::size_t k = 0; k < count.size(); ++k) {
        const auto kind = static_cast<EventKind>(k);
        if (count[k] == 0 || kind == EventKind::program_end) continue;
        out << "event        " << event_name(kind) << " x" << count[k];
        if (kind == EventKind::dwell) {
            out << " (" << fixed_text(dwell, 3) << " s at rest, in the cycle time";
            if (after_last > 0.0) out << "; " << fixed_text(after_last, 3) << " s after the last move, not";
            out << ")";
        }
        out << (event_waits(kind) ? ", motion stops before it\n" : "\n");
    }
}

}  // namespace

void print_summary(std::ostream& out, const PlanRun& run, const std::string& program_name,
                   const std::vector<std::filesystem::path>& written) {
    std::size_t exact = 0, paying = 0;  // stops, and those of them where blending would take longer
    for (const CornerReport& c : run.corners) exact += c.exact_stop ? 1 : 0, paying += c.bound == CornerBound::stop_pays ? 1 : 0;
    const Measured& m = run.measured;
    out << "program      " << program_name << "\n"
        << "machine      " << machine_text(run) << "\n"
        << "blocks       " << run.points.size() - 1 << " moving, " << run.corners.size() << " corners ("
        << exact << " exact stop" << (paying > 0 ? ", " + std::to_string(paying) + " of them faster than blending" : "") << ")\n";
    if (run.program.joined.moves > 0)  // G64 Q: as LinuxCNC's task joins them (naive_cam.hpp)
        out << "naive CAM    " << run.program.joined.moves << " G1 moves joined longer blocks within G64 Q, as LinuxCNC "
            << "joins them (Q0 keeps every move); farthest " << fixed_text(run.program.joined.farthest, 4)
            << " mm from its block; corners and contour measured on the blocks\n";
    out
        << "cycle time   " << fixed_text(run.trajectory.cycle_time, 4) << " s (" << reference_time_text(run) << ")\n"
        << "corners      " << corner_line(run) << "\n"
        << "junctions    slowest " << slowest_junction_text(run) << "\n"
        << "contour      max error " << fixed_text(m.max_contour_error, 4) << " mm\n"
        << "speed        max path " << fixed_text(m.max_path_speed, 1) << " mm/s, axis " << axis_max(m.max_velocity, 1)
        << " mm/s\n"
        << "axes         max acceleration " << axis_max(m.max_acceleration, 0) << " mm/s^2, jerk "
        << axis_max(m.max_jerk, 0) << " mm/s^3\n";
    print_events(out, run.program, run.blocks);
    for (const auto& path : written) out << "wrote        " << path.string() << "\n";
}

}  // namespace firtp::cli
