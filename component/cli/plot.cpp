#include "plot.hpp"

#include "gnuplot_pipe.hpp"
#include "number_text.hpp"
#include <firtp/text_cat.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace firtp::cli {
namespace {

constexpr std::size_t max_program_rows = 20000;  // programmed points drawn (every k-th beyond)

// Script text builder: numbers in round-trip form, lines ended by '\n'.
struct Script {
    std::string text;
    Script& operator<<(const std::string& s) { text += s; return *this; }
    Script& operator<<(const char* s) { text += s; return *this; }
    Script& operator<<(double v) { append_number(text, v); return *this; }
    Script& operator<<(int v) { text += std::to_string(v); return *this; }
    Script& operator<<(std::size_t v) { text += std::to_string(v); return *this; }
};

void row(Script& s, const Eigen::Vector2d& xy) {
    if (xy.allFinite()) s << xy[0] << " " << xy[1] << "\n";
    else s << "\n";  // a run leaving the zoom window
}

void data_blocks(Script& s, const PlanRun& run, const PlotSamples& plot) {
    const std::size_t step = std::max<std::size_t>(1, (run.points.size() + max_program_rows - 1) / max_program_rows);
    s << "$program << EOD\n";
    run.points.for_each([&](std::size_t i, const AxisVector& p) {
        if (i % step == 0) s << p[0] << " " << p[1] << "\n";
    });
    if ((run.points.size() - 1) % step != 0) s << run.points.back()[0] << " " << run.points.back()[1] << "\n";
    s << "EOD\n$path << EOD\n";
    for (const auto& r : plot.path.rows()) s << r[0] << " " << r[1] << "\n";
    s << "EOD\n$time << EOD\n";
    for (const auto& r : plot.time.rows()) s << r[0] << " " << r[1] << " " << r[2] << " " << r[3] << " " << r[4] << "\n";
    s << "EOD\n";
    // The samples near each zoomed corner; runs that leave the window are split by blank lines.
    for (std::size_t z = 0; z < plot.zooms.size(); ++z) {
        s << "$zoom" << z << " << EOD\n";
        for (const Eigen::Vector2d& xy : plot.zooms[z].xy) row(s, xy);
        s << "EOD\n";
    }
}

std::string zoom_title(const PlanRun& run, std::size_t z, const ZoomSamples& zoom) {
    const CornerReport& c = run.corners[zoom.corner];
    const auto& measured = run.corners.error(zoom.corner);
    std::string title = cat("#", std::to_string(z + 1), " line ", std::to_string(c.line), ", ",
                            fixed_text(c.beta * 180.0 / std::numbers::pi, 1), " deg, Tk ", fixed_text(c.Tk * 1e3, 2),
                            " ms\nerror ", measured ? fixed_text(*measured, 4) : std::string("?"));
    if (c.exact_stop) title += " mm (exact stop)";
    else if (std::isfinite(c.epsilon)) title += cat(" / tol ", fixed_text(c.epsilon, 4), " mm");
    else title += " mm, no tol";
    return title;
}

// XY ranges around the program and the path, with a margin, never empty (a line along X, no moves).
void overview_ranges(Script& s, const PlanRun& run, const PlotSamples& plot) {
    Eigen::Vector2d low = run.points.front().head<2>(), high = low;
    const auto grow = [&](const AxisVector& p) {
        low = low.cwiseMin(p.head<2>());
        high = high.cwiseMax(p.head<2>());
    };
    run.points.for_each([&](std::size_t, const AxisVector& p) { grow(p); });
    if (plot.any) {
        low = low.cwiseMin(plot.low);
        high = high.cwiseMax(plot.high);
    }
    const double span = (high - low).maxCoeff();
    const double margin = span > 0.0 ? 0.08 * span : 1.0;
    s << "set xrange [" << low[0] - margin << ":" << high[0] + margin << "]\n"
      << "set yrange [" << low[1] - margin << ":" << high[1] + margin << "]\n";
}

void overview_plot(Script& s, const PlanRun& run, const PlotSamples& plot) {
    const std::vector<ZoomSamples>& zooms = plot.zooms;
    s << "set origin 0,0.44\nset size ratio -1 0.5,0.51\n"
         "set title 'XY path' noenhanced\nset xlabel 'x [mm]'\nset ylabel 'y [mm]'\nset key below horizontal\n";
    overview_ranges(s, run, plot);
    for (std::size_t z = 0; z < zooms.size(); ++z) {
        const AxisVector& c = run.corners[zooms[z].corner].point;
        s << "set label " << (z + 1) << " '#" << (z + 1) << "' at " << c[0] << "," << c[1]
          << " offset 0.8,0.8 front tc 'dark-red'\n";
    }
    s << "plot $program with linespoints lc 'gray40' lw 1.5 pt 7 ps 0.6 title 'programmed', "
         "$path with lines lc 'blue' lw 1.5 title 'planned', "
         "keyentry with lines lc 'red' dashtype 2 title 'tolerance (zooms)'\n"
         "unset label\n";
}

void zoom_plot(Script& s, const PlanRun& run, std::size_t z, const ZoomSamples& zoom) {
    const CornerReport& c = run.corners[zoom.corner];
    const double h = zoom.half_width;
    const double x = 0.5 + 0.25 * static_cast<double>(z % 2);
    const double y = 0.695 - 0.255 * static_cast<double>(z / 2);
    s << "set origin " << x << "," << y << "\nset size ratio -1 0.25,0.255\n"
      << "set title " << gnuplot_quote(zoom_title(run, z, zoom)) << " noenhanced\n"
      << "set xrange [" << c.point[0] - h << ":" << c.point[0] + h << "]\n"
      << "set yrange [" << c.point[1] - h << ":" << c.point[1] + h << "]\n"
      << "unset xlabel\nunset ylabel\nset key off\n";
    if (!c.exact_stop && std::isfinite(c.epsilon) && c.epsilon > 0.0)
        s << "set object 1 circle at " << c.point[0] << "," << c.point[1] << " size " << c.epsilon
          << " front fillstyle empty border lc 'red' dashtype 2\n";
    s << "plot $program with linespoints lc 'gray40' lw 1.5 pt 7 ps 0.6, "
      << "$zoom" << z << " with linespoints lc 'blue' pt 7 ps 0.25\n"
      << "unset object 1\nset autoscale xy\n";
}

// A fixed y range when every value is zero (gnuplot warns on an empty range).
std::string flat_range(bool flat) { return flat ? "set yrange [-1:1]\n" : "set autoscale y\n"; }

void time_plots(Script& s, const PlanRun& run, const PlotSamples& plot) {
    const double feed = plot.max_feed, acceleration = plot.max_acceleration;
    s << "set size noratio 1,0.22\nset key inside top right\nset xlabel 't [s]'\nset grid\n"
      << "set xrange [0:" << std::max(run.trajectory.cycle_time, 1e-3) << "]\n";
    s << "set origin 0,0.22\nset title 'feed (path speed)'\nset ylabel 'mm/s'\n" << flat_range(feed == 0.0)
      << "plot $time using 1:2 with lines lc 'blue' lw 1.5 title 'feed'\n";
    s << "set origin 0,0\nset title 'axis acceleration'\nset ylabel 'mm/s^2' noenhanced\n"
      << flat_range(acceleration == 0.0)
      << "plot $time using 1:3 with lines lw 1.5 title 'a_x' noenhanced, "
         "$time using 1:4 with lines lw 1.5 title 'a_y' noenhanced, "
         "$time using 1:5 with lines lw 1.5 title 'a_z' noenhanced\n";
}

}  // namespace

std::string plot_script(const PlanRun& run, const PlotSamples& plot, const std::string& program_name,
                        const std::filesystem::path& png) {
    const std::vector<ZoomSamples>& zooms = plot.zooms;
    Script s;
    s << "set terminal pngcairo size 1200,1400 font 'Sans,10'\n"
      << "set output " << gnuplot_quote(png.string()) << "\n";
    data_blocks(s, run, plot);
    const std::string title = cat(program_name, ": cycle time ", fixed_text(run.trajectory.cycle_time, 4),
                                  " s, max corner error ", fixed_text(run.measured.max_corner_error, 4), " mm");
    s << "set multiplot title " << gnuplot_quote(title) << " noenhanced font 'Sans,14'\n";
    overview_plot(s, run, plot);
    for (std::size_t z = 0; z < zooms.size(); ++z) zoom_plot(s, run, z, zooms[z]);
    time_plots(s, run, plot);
    s << "unset multiplot\nset output\n";
    return s.text;
}

void write_plot(const PlanRun& run, const PlotSamples& plot, const std::string& program_name,
                const std::filesystem::path& gnuplot, const std::filesystem::path& png) {
    run_gnuplot(gnuplot, plot_script(run, plot, program_name, png));
}

}  // namespace firtp::cli
