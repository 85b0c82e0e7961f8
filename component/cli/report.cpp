#include "report.hpp"

#include "gnuplot_pipe.hpp"
#include "number_text.hpp"
#include "output_files.hpp"
#include "plan_text.hpp"
#include "plan_sink.hpp"
#include "plot.hpp"
#include "vibration_plot.hpp"
#include "vibration_study.hpp"
#include "vibration_table.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <system_error>

namespace firtp::cli {
namespace {

constexpr std::size_t max_corner_rows = 200;
constexpr std::size_t max_plot_rows = 4000;
constexpr int max_plotted_axes = 3;

std::string ms(double seconds) { return fixed_text(seconds * 1e3, 3); }

std::string letter(int axis) { return std::string(1, axis_letters[axis]); }

// Axes that move, in order, at most three (X Y Z first when they move).
std::vector<int> moving_axes(const PlanRun& run) {
    std::vector<int> axes;
    for (int a = 0; a < run.machine.limits.axes && static_cast<int>(axes.size()) < max_plotted_axes; ++a)
        if (run.measured.max_velocity[a] > 0.0) axes.push_back(a);
    if (axes.empty()) axes.push_back(0);
    return axes;
}

std::string modes_text(const MachineConfig& machine) {
    if (machine.tuning.modes.empty()) return "none given";
    std::string text;
    for (std::size_t i = 0; i < machine.tuning.modes.size(); ++i) {
        const StructuralMode& m = machine.tuning.modes[i];
        text += cat(i ? ", " : "", m.axis >= 0 ? letter(m.axis) + " " : "every axis ", fixed_text(m.frequency_hz, 2),
                    " Hz (damping ", fixed_text(m.damping, 3), ")");
    }
    const char* robust[] = {"one stage a mode", "two stages on each mode", "two stages straddling each mode"};
    return cat(text, "; ", robust[static_cast<int>(machine.tuning.robust)]);
}

void summary_table(std::ostream& md, const PlanRun& run, const std::string& name) {
    std::size_t exact = 0;
    for (const CornerReport& c : run.corners) exact += c.exact_stop ? 1 : 0;
    double worst = 0.0;
    std::size_t over = 0;
    for (std::size_t i = 0; i < run.corners.size(); ++i)
        if (run.corners.error(i)) {
            worst = std::max(worst, *run.corners.error(i));
            over += *run.corners.error(i) > run.corners[i].epsilon ? 1 : 0;
        }
    const Measured& m = run.measured;
    md << "| | |\n|---|---|\n"
       << "| program | `" << name << "`: " << run.points.size() - 1 << " blocks that move, " << run.corners.size()
       << " corners (" << exact << " exact stop) |\n"
       << "| machine | " << machine_text(run) << " |\n"
       << "| structural modes | " << modes_text(run.machine) << " |\n"
       << "| cycle time | " << fixed_text(run.trajectory.cycle_time, 4) << " s (" << reference_time_text(run)
       << (run.parameters.fixed_chain ? ": sum(Tv) + sum(Td - Tk) + Td" : ": sum(Tv)") << ") |\n"
       << "| junctions | slowest " << slowest_junction_text(run) << " |\n"
       << "| corner error | max " << fixed_text(worst, 4) << " mm; " << over << " corner(s) above tolerance |\n"
       << "| contour error | max " << fixed_text(m.max_contour_error, 4) << " mm |\n"
       << "| feed | max path speed " << fixed_text(m.max_path_speed, 1) << " mm/s |\n"
       << "| end point | error " << number_text((m.end_position - run.points.back()).norm()) << " mm |\n";
}

void kinematics_table(std::ostream& md, const PlanRun& run) {
    const MachineLimits planned = planned_limits(run.parameters);
    const auto limit = [](double value) { return value > 0.0 ? fixed_text(value, 1) : std::string("-"); };
    md << "Measured on the servo samples (finite differences, what a drive computes) against the axis limits "
          "and what the plan may use of them at 100 % "
       << (run.parameters.fixed_chain ? "(the rest is the rate reserve for the override's clock ramps).\n\n"
                                      : "(all of them: the override is planned like any other speed).\n\n")
       << "| axis | max velocity | limit | max acceleration | planned limit | limit | max jerk | planned limit | limit |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (int a = 0; a < run.machine.limits.axes; ++a) {
        const AxisLimits& l = run.parameters.limits.axis[a];
        const AxisLimits& p = planned.axis[a];
        md << "| " << letter(a) << " | " << fixed_text(run.measured.max_velocity[a], 1) << " | " << limit(l.max_velocity)
           << " | " << fixed_text(run.measured.max_acceleration[a], 0) << " | " << limit(p.max_acceleration) << " | "
           << limit(l.max_acceleration) << " | " << fixed_text(run.measured.max_jerk[a], 0) << " | "
           << limit(p.max_jerk) << " | " << limit(l.max_jerk) << " |\n";
    }
    md << "\nUnits: mm (degrees for A B C), seconds.\n";
}

void corner_table(std::ostream& md, const PlanRun& run) {
    const auto& corners = run.corners;
    if (corners.empty()) {
        md << "No corners.\n";
        return;
    }
    const bool chain = run.parameters.fixed_chain;
    md << "The error is the closest approach of the sampled path (straight between samples) to the programmed "
          "corner point, measured by `component/analysis` from the samples alone; *predicted* is the planner's "
          "check. "
       << (chain ? "Tk is the overlap of the two blocks' pulses (Eq. 11)."
                 : "The speeds are the command's before and after the junction; *bound* is what limited them.")
       << "\n\n| # | line | turn (deg) | " << (chain ? "Tk (ms)" : "speed in / out (mm/s) | bound")
       << " | tolerance (mm) | predicted (mm) | measured (mm) |\n|---:|---:|---:|" << (chain ? "---:" : "---:|---")
       << "|---:|---:|---:|\n";
    for (std::size_t i = 0; i < corners.size() && i < max_corner_rows; ++i) {
        const CornerReport& c = corners[i];
        md << "| " << i + 1 << " | " << c.line << " | " << fixed_text(c.beta * 180.0 / std::numbers::pi, 1) << " | ";
        if (chain) md << (c.exact_stop ? std::string("stop") : ms(c.Tk));
        else md << fixed_text(c.speed_in, 1) << " / " << fixed_text(c.speed_out, 1) << " | " << bound_text(c);
        md << " | " << (std::isfinite(c.epsilon) ? fixed_text(c.epsilon, 4) : std::string("none")) << " | "
           << fixed_text(c.predicted_error, 4) << " | "
           << (run.corners.error(i) ? fixed_text(*run.corners.error(i), 4) : std::string("?")) << " |\n";
    }
    if (corners.size() > max_corner_rows)
        md << "\n" << corners.size() - max_corner_rows << " more corners: see `firtp plan --json`.\n";
}

std::string kinematics_script(const PlanRun& run, const std::vector<int>& axes, const std::filesystem::path& png) {
    const auto& samples = run.trajectory.samples;
    const std::size_t step = std::max<std::size_t>(1, (samples.size() + max_plot_rows - 1) / max_plot_rows);
    std::string s = cat("set terminal pngcairo size 1200,1000 font 'Sans,10'\nset output ", gnuplot_quote(png.string()),
                        "\n$k << EOD\n");
    for (std::size_t k = 0; k < samples.size(); k += step) {
        append_number(s, samples[k].time);
        for (int a : axes)
            for (const AxisVector* v : {&samples[k].velocity, &samples[k].acceleration, &samples[k].jerk}) {
                s += " ";
                append_number(s, (*v)[a]);
            }
        s += "\n";
    }
    s += cat("EOD\nset multiplot title ", gnuplot_quote(cat(run.program.file, ": axis kinematics (the chain's exact values at the samples)")),
             " noenhanced font 'Sans,13' layout 3,1\nset grid\nset key outside right top\nset lmargin at screen 0.08\n"
             "set rmargin at screen 0.86\nset xlabel 't [s]'\n");
    const char* titles[] = {"velocity", "acceleration", "jerk"};
    const char* units[] = {"mm/s", "mm/s^2", "mm/s^3"};
    for (int q = 0; q < 3; ++q) {
        s += cat("set title '", titles[q], "'\nset ylabel '", units[q], "' noenhanced\nplot ");
        for (std::size_t i = 0; i < axes.size(); ++i)
            s += cat(i ? ", " : "", "$k using 1:", std::to_string(2 + 3 * i + static_cast<std::size_t>(q)),
                     " with lines lw 1.3 title '", letter(axes[i]), "'");
        s += "\n";
    }
    return s + "unset multiplot\nset output\n";
}

SpectrumPlot plan_spectrum(const PlanRun& run, const std::vector<int>& axes) {
    SpectrumPlot plot;
    plot.title = cat(run.program.file, ": acceleration spectra and the filter chain");
    plot.axes = axes;
    plot.series.push_back({"firtp", &run.trajectory.samples});
    plot.chains.push_back({chain_label("firtp", run.parameters.filters), run.parameters.filters});
    plot.max_hz = spectrum_range(plot.marks, plot.chains);
    return plot;
}

}  // namespace

void make_output_directory(const std::filesystem::path& dir) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error || !std::filesystem::is_directory(dir))
        throw std::runtime_error(cat("cannot create directory '", dir.string(), "': ",
                                     error ? error.message() : std::string("not a directory")));
}

std::vector<std::filesystem::path> write_report(const PlanRun& run, const PlanOptions& options,
                                                const std::filesystem::path& gnuplot) {
    const std::filesystem::path& dir = *options.report;
    const std::string name = options.program.filename().string();
    const std::vector<int> axes = moving_axes(run);
    std::optional<VibrationStudy> study;
    if (!run.machine.tuning.modes.empty()) study = study_vibration(run.machine, options.program, 0.0);

    make_output_directory(dir);
    OutputFiles outputs;
    std::vector<std::filesystem::path> written{dir / "report.md", dir / "path.png", dir / "kinematics.png",
                                               dir / "spectrum.png"};
    if (study) written.push_back(dir / "response.png");
    write_plot(run, plot_samples_of(run), name, gnuplot, outputs.create(written[1]));
    run_gnuplot(gnuplot, kinematics_script(run, axes, outputs.create(written[2])));
    const SpectrumPlot spectrum = study ? study_spectrum(*study) : plan_spectrum(run, axes);
    run_gnuplot(gnuplot, spectrum_plot_script(spectrum, outputs.create(written[3])));
    if (study) run_gnuplot(gnuplot, response_plot_script(*study, outputs.create(written[4])));

    outputs.write(written[0], [&](std::ostream& md) {
        md << "# firtp plan: " << name << "\n\n";
        summary_table(md, run, name);
        md << "\n## Path and feed\n\nThe planned path over the programmed one, the corners with the largest errors "
              "zoomed (red circle: the tolerance), the path speed and the axis accelerations.\n\n![path](path.png)\n"
           << "\n## Axis kinematics\n\n";
        kinematics_table(md, run);
        md << "\n![kinematics](kinematics.png)\n\n## Corners\n\n";
        corner_table(md, run);
        md << "\n## Spectrum\n\nThe chain multiplies the spectrum of the programmed velocity pulses by "
              "|M(j 2 pi f)| = prod |sin(pi f T_i) / (pi f T_i)| (Eq. 8-9): zeros at f = k / T_i. A structural mode on "
              "such a zero is not excited.\n\n![spectrum](spectrum.png)\n";
        if (study) md << "\n" << vibration_markdown(*study, "##") << "\n![mode deflection](response.png)\n";
        md << "\n---\nWritten by `firtp plan " << name << " --report " << dir.filename().string() << "`.\n";
    });
    outputs.commit();
    return written;
}

}  // namespace firtp::cli
