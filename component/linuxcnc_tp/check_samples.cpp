// firtp-tp-check: measures what LinuxCNC commanded, period by period, against the program.
//
//   firtp-tp-check SAMPLES --ini INI --program NGC [--tp-samples FILE] [--tolerance MM]
//                  [--corner-tolerance MM] [--limits] [--jerk J] [--cycle-time S[:WITHIN]]
//                  [--lines N,N,...] [--stopped] [--hold S] [--reference CSV [--within MM]]
//                  [--tsc-hz HZ] [--json FILE]
//   firtp-tp-check --tsc-hz       prints the time-stamp counter's frequency (what HAL's .time counts)
//
// SAMPLES is what examples/linuxcnc/record.hal records through halsampler, one line a servo period:
// X Y Z (the planner's output, scaled by 2^40), motion.program-line, motion-controller.time and
// motion-command-handler.time (TSC clocks), motion.in-position. --tp-samples: firtp_tp's own
// pins (adds, add-ns, cycle-ns, plan-ns, planned), recorded by bin/firtp-headless.
//
// The programmed path is the program read by firtp's G-code reader from the first sample's
// position, with the INI's period and limits (arcs as chords of [FIRTP]ARC_CHORD_TOLERANCE,
// 0.001 mm). The measurement is component/analysis's: contour error (distance of every sample
// from the programmed polyline), corner errors, per-axis velocity, acceleration and jerk from
// finite differences of the samples (what a drive computes), cycle time from the first moving
// sample to the first at rest at the end. Checks, each failing the exit status (1): the end is the
// program's end; with --tolerance the contour error, with --corner-tolerance the corner errors,
// with --limits every axis' MAX_VELOCITY and MAX_ACCELERATION, with --jerk the jerk of every axis,
// with --cycle-time the cycle time (default within 2 ms), with --lines the program lines that
// motion.program-line (tpGetExecId) showed while the tool moved, in order. --stopped: the program
// was aborted, so the tool must rest on the path (the last samples equal) short of its end.
// --hold S: somewhere inside the motion the tool rested at least S seconds (a pause).
// --reference CSV: `firtp plan --csv` of the same program and machine; every period of the
// motion must equal it within --within (1e-9 mm), and both must last as long.
#include <firtp/gcode.hpp>
#include <firtp/ini.hpp>
#include <firtp/machine.hpp>
#include <firtp/measure.hpp>
#include <firtp/version.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace {

constexpr double position_scale = 1099511627776.0;  // 2^40, as record.hal's scale components
constexpr std::size_t columns = 7;

struct Row {
    firtp::AxisVector position = firtp::AxisVector::Zero();
    long line = 0;
    double controller_clocks = 0.0;
    double command_clocks = 0.0;
    bool in_position = false;
};

struct TpRow {
    long adds = 0;
    double add_ns = 0.0, cycle_ns = 0.0, plan_ns = 0.0;
    long planned = 0;
};

[[noreturn]] void usage(const std::string& why) {
    std::cerr << "firtp-tp-check: " << why << "\n"
              << "usage: firtp-tp-check SAMPLES --ini INI --program NGC [--tp-samples FILE] [--tolerance MM]\n"
                 "                      [--corner-tolerance MM] [--limits] [--jerk J] [--cycle-time S[:WITHIN]]\n"
                 "                      [--lines N,N,...] [--stopped] [--hold S] [--reference CSV [--within MM]]\n"
                 "                      [--tsc-hz HZ] [--json FILE]\n"
                 "       firtp-tp-check --tsc-hz\n";
    std::exit(2);
}

double measure_tsc_hz() {
#if defined(__x86_64__) || defined(__i386__)
    const auto t0 = std::chrono::steady_clock::now();
    const unsigned long long c0 = __rdtsc();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const unsigned long long c1 = __rdtsc();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return static_cast<double>(c1 - c0) / seconds;
#else
    return 0.0;
#endif
}

std::vector<std::vector<std::string>> read_rows(const std::string& path, std::size_t width, long& overruns) {
    std::ifstream in(path);
    if (!in) usage("cannot read " + path);
    std::vector<std::vector<std::string>> rows;
    std::string text;
    overruns = 0;
    while (std::getline(in, text)) {
        std::istringstream words(text);
        std::vector<std::string> row;
        for (std::string w; words >> w;) row.push_back(w);
        if (row.empty()) continue;
        if (row[0] == "overrun") {
            ++overruns;
            continue;
        }
        if (row.size() < width) usage(path + ": a line with " + std::to_string(row.size()) + " columns, expected " +
                                      std::to_string(width));
        rows.push_back(row);
    }
    return rows;
}

struct Stats {
    double median = 0.0, p99 = 0.0, max = 0.0;
    std::size_t count = 0;
};

Stats stats(std::vector<double> v) {
    Stats s;
    s.count = v.size();
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    s.median = v[v.size() / 2];
    s.p99 = v[std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(v.size()))) - 1)];
    s.max = v.back();
    return s;
}

nlohmann::json stats_json(const Stats& s) {
    return {{"median_us", s.median}, {"p99_us", s.p99}, {"max_us", s.max}, {"cycles", s.count}};
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() == 1 && args[0] == "--version") {
        std::printf("firtp-tp-check %s\n", firtp::version);
        return 0;
    }
    if (args.size() == 1 && args[0] == "--tsc-hz") {
        std::printf("%.0f\n", measure_tsc_hz());
        return 0;
    }
    std::string samples_path, ini_path, program_path, tp_samples_path, json_path, reference_path;
    double within = 1e-9;
    double tolerance = -1.0, corner_tolerance = -1.0, jerk = -1.0, tsc_hz = 0.0;
    double cycle_time = -1.0, cycle_within = 0.002;
    std::vector<long> expected_lines;
    bool limits = false, stopped = false;
    double hold = -1.0;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size()) usage(a + " needs a value");
            return args[++i];
        };
        auto number = [&]() {
            const std::string v = value();
            char* end = nullptr;
            const double d = std::strtod(v.c_str(), &end);
            if (end == v.c_str() || *end != '\0' || !std::isfinite(d)) usage(a + ": '" + v + "' is not a number");
            return d;
        };
        if (a == "--ini") ini_path = value();
        else if (a == "--program") program_path = value();
        else if (a == "--tp-samples") tp_samples_path = value();
        else if (a == "--json") json_path = value();
        else if (a == "--tolerance") tolerance = number();
        else if (a == "--corner-tolerance") corner_tolerance = number();
        else if (a == "--jerk") jerk = number();
        else if (a == "--tsc-hz") tsc_hz = number();
        else if (a == "--limits") limits = true;
        else if (a == "--stopped") stopped = true;
        else if (a == "--hold") hold = number();
        else if (a == "--reference") reference_path = value();
        else if (a == "--within") within = number();
        else if (a == "--cycle-time") {
            const std::string v = value();
            char* end = nullptr;
            cycle_time = std::strtod(v.c_str(), &end);
            if (*end == ':') cycle_within = std::strtod(end + 1, &end);
            if (*end != '\0' || !(cycle_time > 0.0) || !(cycle_within >= 0.0)) usage("--cycle-time S[:WITHIN]");
        } else if (a == "--lines") {
            std::istringstream list(value());
            for (std::string n; std::getline(list, n, ',');) expected_lines.push_back(std::strtol(n.c_str(), nullptr, 10));
        }
        else if (!a.empty() && a[0] == '-') usage("unknown option " + a);
        else if (samples_path.empty()) samples_path = a;
        else usage("one samples file only");
    }
    if (samples_path.empty() || ini_path.empty() || program_path.empty()) usage("SAMPLES, --ini and --program are needed");

    firtp::MachineConfig machine;
    firtp::Program program;
    long overruns = 0;
    const auto raw = read_rows(samples_path, columns, overruns);
    if (raw.size() < 2) usage(samples_path + ": fewer than two samples");
    std::vector<Row> rows;
    for (const auto& r : raw) {
        Row row;
        for (int a = 0; a < 3; ++a) row.position[a] = std::strtod(r[static_cast<std::size_t>(a)].c_str(), nullptr) / position_scale;
        row.line = std::strtol(r[3].c_str(), nullptr, 10);
        row.controller_clocks = std::strtod(r[4].c_str(), nullptr);
        row.command_clocks = std::strtod(r[5].c_str(), nullptr);
        row.in_position = r[6] == "1";
        rows.push_back(row);
    }
    try {
        machine = firtp::load_machine(firtp::IniFile::read(ini_path));
        program = firtp::read_gcode(program_path, machine, rows.front().position);
    } catch (const std::exception& e) {
        std::cerr << "firtp-tp-check: " << e.what() << "\n";
        return 2;
    }

    // The motion: from the last sample at rest before it to the first at rest at its end.
    std::size_t first = 0, last = rows.size() - 1;
    while (first + 1 < rows.size() && rows[first + 1].position == rows[first].position) ++first;
    while (last > first && rows[last - 1].position == rows[last].position) --last;
    std::vector<firtp::AxisState> samples;
    for (std::size_t k = first; k <= last; ++k) {
        firtp::AxisState s;
        s.time = static_cast<double>(k - first) * machine.period;
        s.position = rows[k].position;
        samples.push_back(s);
    }
    std::vector<firtp::AxisVector> points{program.start};
    for (const firtp::Block& b : program.blocks) points.push_back(b.target);
    const firtp::Measured m = firtp::measure(samples, points, machine.period);
    const double end_error = (rows.back().position - points.back()).norm();

    // CPU time of the two motion functions over the motion (clocks -> us).
    if (tsc_hz <= 0.0) tsc_hz = measure_tsc_hz();
    std::vector<double> controller, command;
    for (std::size_t k = first; k <= last; ++k) {
        controller.push_back(rows[k].controller_clocks / tsc_hz * 1e6);
        command.push_back(rows[k].command_clocks / tsc_hz * 1e6);
    }
    const Stats controller_stats = stats(controller), command_stats = stats(command);

    nlohmann::json report = {
        {"samples", rows.size()},
        {"overruns", overruns},
        {"moving_samples", samples.size()},
        {"cycle_time_s", m.cycle_time},
        {"max_contour_error_mm", m.max_contour_error},
        {"max_corner_error_mm", m.max_corner_error},
        {"max_path_speed", m.max_path_speed},
        {"end_error_mm", end_error},
        {"program_blocks", program.blocks.size()},
        {"tsc_hz", tsc_hz},
        {"motion_controller", stats_json(controller_stats)},
        {"motion_command_handler", stats_json(command_stats)},
    };
    double max_v = 0.0, max_a = 0.0, max_j = 0.0;
    for (int a = 0; a < 3; ++a) {
        max_v = std::max(max_v, m.max_velocity[a]);
        max_a = std::max(max_a, m.max_acceleration[a]);
        max_j = std::max(max_j, m.max_jerk[a]);
    }
    report["max_axis_velocity"] = {m.max_velocity[0], m.max_velocity[1], m.max_velocity[2]};
    report["max_axis_acceleration"] = {m.max_acceleration[0], m.max_acceleration[1], m.max_acceleration[2]};
    report["max_axis_jerk"] = {m.max_jerk[0], m.max_jerk[1], m.max_jerk[2]};

    // firtp_tp's own measurements: per add (periods whose add counter moved) and per cycle.
    if (!tp_samples_path.empty()) {
        long tp_overruns = 0;
        const auto tp_raw = read_rows(tp_samples_path, 5, tp_overruns);
        std::vector<double> add, cycle, plan;
        long most_planned = 0, previous_adds = -1;
        for (const auto& r : tp_raw) {
            const long adds = std::strtol(r[0].c_str(), nullptr, 10);
            if (previous_adds >= 0 && adds != previous_adds) add.push_back(std::strtod(r[1].c_str(), nullptr) / 1e3);
            previous_adds = adds;
            cycle.push_back(std::strtod(r[2].c_str(), nullptr) / 1e3);
            plan.push_back(std::strtod(r[3].c_str(), nullptr) / 1e3);
            most_planned = std::max(most_planned, std::strtol(r[4].c_str(), nullptr, 10));
        }
        report["firtp_tp"] = {{"add", stats_json(stats(add))},
                              {"run_cycle", stats_json(stats(cycle))},
                              {"planning", stats_json(stats(plan))},
                              {"most_blocks_planned_in_a_period", most_planned},
                              {"overruns", tp_overruns}};
    }

    // The longest rest inside the motion (a pause), in seconds.
    double longest_rest = 0.0;
    for (std::size_t k = first + 1, run = 0; k <= last; ++k) {
        run = rows[k].position == rows[k - 1].position ? run + 1 : 0;
        longest_rest = std::max(longest_rest, static_cast<double>(run) * machine.period);
    }
    report["longest_rest_s"] = longest_rest;

    // Program lines while moving, each once in the order they came.
    std::vector<long> lines;
    for (std::size_t k = first; k <= last; ++k)
        if (rows[k].line != 0 && (lines.empty() || lines.back() != rows[k].line)) lines.push_back(rows[k].line);
    report["lines"] = lines;

    std::vector<std::string> failures;
    auto fail = [&](const std::string& what) { failures.push_back(what); };
    char text[256];
    if (overruns > 0) fail("the sampler lost samples (" + std::to_string(overruns) + " overruns)");
    if (!m.finite) fail("a sample is not finite");
    if (stopped) {
        const std::size_t n = rows.size();
        if (n < 20 || rows[n - 1].position != rows[n - 20].position) fail("the tool did not come to rest");
        if (end_error < 1e-6) fail("the tool reached the program's end: nothing was stopped");
    } else if (end_error > 1e-9) {
        std::snprintf(text, sizeof text, "the tool ends %.6g mm from the program's end", end_error);
        fail(text);
    }
    if (tolerance >= 0.0 && m.max_contour_error > tolerance * (1 + 1e-9)) {
        std::snprintf(text, sizeof text, "contour error %.6f mm > tolerance %.6f mm", m.max_contour_error, tolerance);
        fail(text);
    }
    if (corner_tolerance >= 0.0 && m.max_corner_error > corner_tolerance * (1 + 1e-9)) {
        std::snprintf(text, sizeof text, "corner error %.6f mm > tolerance %.6f mm", m.max_corner_error, corner_tolerance);
        fail(text);
    }
    for (int a = 0; a < 3; ++a) {
        const firtp::AxisLimits& l = machine.limits.axis[static_cast<std::size_t>(a)];
        const char axis = firtp::axis_letters[static_cast<std::size_t>(a)];
        if (limits && l.max_velocity > 0.0 && m.max_velocity[a] > l.max_velocity * (1 + 1e-9)) {
            std::snprintf(text, sizeof text, "%c velocity %.3f > MAX_VELOCITY %.3f", axis, m.max_velocity[a], l.max_velocity);
            fail(text);
        }
        if (limits && l.max_acceleration > 0.0 && m.max_acceleration[a] > l.max_acceleration * (1 + 1e-6)) {
            std::snprintf(text, sizeof text, "%c acceleration %.1f > MAX_ACCELERATION %.1f", axis, m.max_acceleration[a],
                          l.max_acceleration);
            fail(text);
        }
        if (jerk > 0.0 && m.max_jerk[a] > jerk * (1 + 1e-6)) {
            std::snprintf(text, sizeof text, "%c jerk %.0f > %.0f", axis, m.max_jerk[a], jerk);
            fail(text);
        }
    }
    if (!reference_path.empty()) {
        // firtp plan's CSV: t,x,y,z,... one row a period from rest at the start to rest at the end.
        std::ifstream in(reference_path);
        if (!in) usage("cannot read " + reference_path);
        std::vector<firtp::AxisVector> plan;
        std::string row;
        std::getline(in, row);  // header
        while (std::getline(in, row)) {
            std::istringstream fields(row);
            std::string field;
            firtp::AxisVector p = firtp::AxisVector::Zero();
            std::getline(fields, field, ',');  // t
            for (int a = 0; a < 3 && std::getline(fields, field, ','); ++a) p[a] = std::strtod(field.c_str(), nullptr);
            plan.push_back(p);
        }
        double largest = 0.0;
        const std::size_t n = std::min(plan.size(), samples.size());
        for (std::size_t k = 0; k < n; ++k) largest = std::max(largest, (samples[k].position - plan[k]).norm());
        report["reference_periods"] = plan.size();
        report["largest_difference_from_reference_mm"] = largest;
        std::printf("reference    %zu periods planned offline, %zu recorded; largest difference %.3g mm\n", plan.size(),
                    samples.size(), largest);
        if (plan.size() != samples.size()) {
            std::snprintf(text, sizeof text, "%zu periods recorded, %zu in %s", samples.size(), plan.size(),
                          reference_path.c_str());
            fail(text);
        }
        if (!(largest <= within)) {
            std::snprintf(text, sizeof text, "differs from the offline plan by %.3g mm (allowed %.3g)", largest, within);
            fail(text);
        }
    }
    if (hold > 0.0 && longest_rest < hold) {
        std::snprintf(text, sizeof text, "the tool rested at most %.3f s inside the motion, expected %.3f s", longest_rest,
                      hold);
        fail(text);
    }
    if (cycle_time > 0.0 && std::abs(m.cycle_time - cycle_time) > cycle_within) {
        std::snprintf(text, sizeof text, "cycle time %.4f s, expected %.4f +- %.4f s", m.cycle_time, cycle_time,
                      cycle_within);
        fail(text);
    }
    if (!expected_lines.empty() && lines != expected_lines) {
        std::string seen;
        for (long l : lines) {
            if (!seen.empty()) seen += ',';
            seen += std::to_string(l);
        }
        fail("program lines while moving were " + seen);
    }
    report["failures"] = failures;

    std::printf("samples      %zu (%zu moving), %ld overruns\n", rows.size(), samples.size(), overruns);
    std::printf("cycle time   %.4f s; %zu program lines while moving; longest rest inside %.3f s\n", m.cycle_time,
                lines.size(), longest_rest);
    std::printf("contour      max error %.4f mm; corners max %.4f mm; end %.3g mm off\n", m.max_contour_error,
                m.max_corner_error, end_error);
    std::printf("axes         max velocity %.1f, acceleration %.0f, jerk %.0f (units/s^n, 1 ms differences)\n", max_v,
                max_a, max_j);
    std::printf("cpu          motion-controller median %.1f us, p99 %.1f, max %.1f; motion-command-handler median "
                "%.1f us, p99 %.1f, max %.1f\n",
                controller_stats.median, controller_stats.p99, controller_stats.max, command_stats.median,
                command_stats.p99, command_stats.max);
    if (report.contains("firtp_tp")) {
        const auto& t = report["firtp_tp"];
        std::printf("firtp_tp     tpAdd* median %.1f us, max %.1f (%zu adds); tpRunCycle median %.1f us, p99 %.1f, max %.1f; "
                    "at most %ld blocks planned in a period\n",
                    t["add"]["median_us"].get<double>(), t["add"]["max_us"].get<double>(),
                    t["add"]["cycles"].get<std::size_t>(), t["run_cycle"]["median_us"].get<double>(),
                    t["run_cycle"]["p99_us"].get<double>(), t["run_cycle"]["max_us"].get<double>(),
                    t["most_blocks_planned_in_a_period"].get<long>());
    }
    for (const std::string& f : failures) std::printf("FAIL         %s\n", f.c_str());
    if (!json_path.empty()) {
        std::ofstream out(json_path);
        out << report.dump(1) << "\n";
        if (!out) {
            std::cerr << "firtp-tp-check: cannot write " << json_path << "\n";
            return 2;
        }
    }
    return failures.empty() ? 0 : 1;
}
