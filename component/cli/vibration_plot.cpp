#include "vibration_plot.hpp"

#include "gnuplot_pipe.hpp"
#include "number_text.hpp"

#include <firtp/mode_response.hpp>
#include <firtp/mode_tuning.hpp>
#include <firtp/text_cat.hpp>

#include <algorithm>
#include <cmath>

namespace firtp::cli {
namespace {

constexpr std::size_t max_rows = 4000;       // points a curve keeps
constexpr double spectrum_step = 0.05;       // Hz
constexpr double log_floor = 1e-7;           // of each panel's peak: zeros drawn at the floor
const char* const colours[] = {"#1f77b4", "#ff7f0e", "#7f7f7f", "#2ca02c", "#d62728"};

struct Script {
    std::string text;
    Script& operator<<(const std::string& s) { text += s; return *this; }
    Script& operator<<(const char* s) { text += s; return *this; }
    Script& operator<<(double v) { append_number(text, v); return *this; }
    Script& operator<<(std::size_t v) { text += std::to_string(v); return *this; }
    Script& operator<<(int v) { text += std::to_string(v); return *this; }
};

std::string colour(std::size_t i) { return cat("'", colours[i % std::size(colours)], "'"); }

void mode_marks(Script& s, const std::vector<SpectrumPlot::Mark>& marks) {
    for (std::size_t i = 0; i < marks.size(); ++i)
        s << "set arrow " << (i + 1) << " from first " << marks[i].frequency_hz << ", graph 0 to first "
          << marks[i].frequency_hz << ", graph 1 nohead lc 'red' dashtype 2 lw 1.2\n"
          << "set label " << (i + 1) << " " << gnuplot_quote(marks[i].label) << " at first " << marks[i].frequency_hz
          << ", graph " << 0.93 - 0.08 * static_cast<double>(i % 3) << " offset 0.5,0 tc 'red' noenhanced\n";
}

void unset_marks(Script& s, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) s << "unset arrow " << (i + 1) << "\nunset label " << (i + 1) << "\n";
}

}  // namespace

std::string response_plot_script(const VibrationStudy& study, const std::filesystem::path& png) {
    Script s;
    const std::size_t panels = study.plant.size();
    const int height = static_cast<int>(120 + 300 * panels);
    s << "set terminal pngcairo size 1200," << height << " font 'Sans,10'\n"
      << "set output " << gnuplot_quote(png.string()) << "\n";
    for (std::size_t m = 0; m < panels; ++m)
        for (std::size_t c = 0; c < study.cases.size(); ++c) {
            const PlannerCase& pc = study.cases[c];
            const ModeResponse& r = pc.responses[m];
            const std::size_t step = std::max<std::size_t>(1, (pc.samples.size() + max_rows - 1) / max_rows);
            s << "$m" << m << "c" << c << " << EOD\n";
            for (std::size_t k = 0; k < pc.samples.size(); k += step) s << pc.samples[k].time << " " << r.deflection[k] << "\n";
            s << "EOD\n";
        }
    s << "set multiplot title "
      << gnuplot_quote(cat(study.program, ": deflection x(t) of each mode, driven by minus its axis's acceleration"))
      << " noenhanced font 'Sans,13' layout " << panels << ",1\n"
      << "set grid\nset key outside right top\nset lmargin at screen 0.07\nset rmargin at screen 0.80\n"
         "set xlabel 't [s]'\nset ylabel 'x [mm]'\n";
    for (std::size_t m = 0; m < panels; ++m) {
        const PlantMode& p = study.plant[m];
        s << "set title " << gnuplot_quote(cat(plant_name(p), ", damping ", fixed_text(p.damping, 3),
                                               ": largest residual at a stop ",
                                               fixed_text(study.cases[0].responses[m].max_stop_residual, 5), " (tuned), ",
                                               fixed_text(study.cases[1].responses[m].max_stop_residual, 5), " (untuned), ",
                                               fixed_text(study.cases[2].responses[m].max_stop_residual, 5),
                                               " mm (S-curve); dotted: end of motion"))
          << " noenhanced\n";
        // Each planner's end of motion, dotted.
        for (std::size_t c = 0; c < study.cases.size(); ++c)
            s << "set arrow " << (c + 1) << " from first " << study.cases[c].cycle_time << ", graph 0 to first "
              << study.cases[c].cycle_time << ", graph 1 nohead lc rgb " << colour(c) << " dashtype 3\n";
        s << "plot ";
        for (std::size_t c = 0; c < study.cases.size(); ++c)
            s << (c ? ", " : "") << "$m" << m << "c" << c << " with lines lw 1.4 lc rgb " << colour(c) << " title "
              << gnuplot_quote(study.cases[c].name) << " noenhanced";
        s << "\n";
        for (std::size_t c = 0; c < study.cases.size(); ++c) s << "unset arrow " << (c + 1) << "\n";
    }
    s << "unset multiplot\nset output\n";
    return s.text;
}

std::string chain_label(const std::string& name, const FilterTimes& filters) {
    std::string text = name + ": T = ";
    for (int i = 0; i < filters.stages; ++i) text += cat(i ? ", " : "", fixed_text(filters.T[i] * 1e3, 1));
    return text + " ms";
}

SpectrumPlot study_spectrum(const VibrationStudy& study) {
    SpectrumPlot plot;
    plot.title = cat(study.program, ": acceleration spectra and the filter chains, modes marked");
    for (const PlantMode& p : study.plant) {
        if (std::find(plot.axes.begin(), plot.axes.end(), p.axis) == plot.axes.end()) plot.axes.push_back(p.axis);
        plot.marks.push_back({plant_name(p), p.frequency_hz});
    }
    for (const PlannerCase& c : study.cases) plot.series.push_back({c.name, &c.samples});
    plot.chains = {{chain_label("tuned", study.tuned.filters), study.tuned.filters},
                   {chain_label("untuned", study.untuned), study.untuned}};
    plot.max_hz = spectrum_range(plot.marks, plot.chains);
    return plot;
}

double spectrum_range(const std::vector<SpectrumPlot::Mark>& marks, const std::vector<SpectrumPlot::Chain>& chains) {
    double range = 30.0;
    for (const auto& m : marks) range = std::max(range, 2.5 * m.frequency_hz);
    for (const auto& c : chains) {
        const double shortest = c.filters.T[static_cast<std::size_t>(std::max(c.filters.stages - 1, 0))];
        if (shortest > 0.0) range = std::max(range, 1.5 / shortest);
    }
    return std::min(range, 500.0);
}

std::string spectrum_plot_script(const SpectrumPlot& plot, const std::filesystem::path& png) {
    std::vector<double> freqs;
    for (double f = spectrum_step; f <= plot.max_hz + 1e-9; f += spectrum_step) freqs.push_back(f);
    const std::size_t panels = plot.axes.size() + (plot.chains.empty() ? 0 : 1);
    Script s;
    s << "set terminal pngcairo size 1200," << static_cast<int>(120 + 300 * panels) << " font 'Sans,10'\n"
      << "set output " << gnuplot_quote(png.string()) << "\n";
    for (std::size_t a = 0; a < plot.axes.size(); ++a)
        for (std::size_t k = 0; k < plot.series.size(); ++k) {
            const std::vector<double> mag = acceleration_spectrum(*plot.series[k].samples, plot.axes[a], freqs);
            const double peak = std::max(*std::max_element(mag.begin(), mag.end()), 1e-300);
            s << "$a" << a << "s" << k << " << EOD\n";
            for (std::size_t i = 0; i < freqs.size(); ++i) s << freqs[i] << " " << std::max(mag[i], log_floor * peak) << "\n";
            s << "EOD\n";
        }
    for (std::size_t c = 0; c < plot.chains.size(); ++c) {
        s << "$chain" << c << " << EOD\n";
        for (const double f : freqs) s << f << " " << std::max(chain_magnitude(plot.chains[c].filters, f), log_floor) << "\n";
        s << "EOD\n";
    }
    s << "set multiplot title " << gnuplot_quote(plot.title) << " noenhanced font 'Sans,13' layout " << panels << ",1\n"
      << "set grid\nset key outside right top\nset lmargin at screen 0.07\nset rmargin at screen 0.74\n"
         "set logscale y\nset format y '10^{%T}'\nset xlabel 'f [Hz]'\n"
      << "set xrange [0:" << plot.max_hz << "]\n";
    mode_marks(s, plot.marks);
    for (std::size_t a = 0; a < plot.axes.size(); ++a) {
        s << "set title " << gnuplot_quote(cat("axis ", std::string(1, axis_letters[plot.axes[a]]),
                                               ": |DFT| of the acceleration (Eq. 9: the chain's magnitude shapes it)"))
          << " noenhanced\nset ylabel '|A(f)| [mm/s]'\nplot ";
        for (std::size_t k = 0; k < plot.series.size(); ++k)
            s << (k ? ", " : "") << "$a" << a << "s" << k << " with lines lw 1.3 lc rgb " << colour(k) << " title "
              << gnuplot_quote(plot.series[k].label) << " noenhanced";
        s << "\n";
    }
    if (!plot.chains.empty()) {
        s << "set title 'the filter chain: |M(j 2 pi f)| = prod |sin(pi f T_i) / (pi f T_i)| (Eq. 8-9), zeros at k / T_i' "
             "noenhanced\nset ylabel '|M|'\nplot ";
        for (std::size_t c = 0; c < plot.chains.size(); ++c)
            s << (c ? ", " : "") << "$chain" << c << " with lines lw 1.3 lc rgb " << colour(c) << " title "
              << gnuplot_quote(plot.chains[c].label) << " noenhanced";
        s << "\n";
    }
    unset_marks(s, plot.marks.size());
    s << "unset multiplot\nset output\n";
    return s.text;
}

}  // namespace firtp::cli
