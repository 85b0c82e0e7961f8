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
// position, with the INI's period and limits (arcs as chords of [FIRTP]ARC_CHORD_TOLERANCE). The measurement is component/analysis's: contour error (distance of every sample
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
//
// options.cpp reads the command line, recording.cpp the recordings, checks.cpp checks them.
#include "checks.hpp"
#include "options.hpp"
#include "recording.hpp"

#include <firtp/gcode.hpp>
#include <firtp/ini.hpp>
#include <firtp/machine.hpp>
#include <firtp/measure.hpp>
#include <firtp/version.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace firtp::tp_check;

// The recording measured against the program; `points` the programmed polyline.
Measurement measure(Recording recording, const firtp::MachineConfig& machine, const firtp::Program& program) {
    Measurement m;
    m.recording = std::move(recording);
    const std::vector<Row>& rows = m.recording.rows;
    m.motion = find_motion(rows);
    m.samples = motion_samples(rows, m.motion, machine.period);
    std::vector<firtp::AxisVector> points{program.start};
    for (const firtp::Block& b : program.blocks) points.push_back(b.target);
    m.measured = firtp::measure(m.samples, points, machine.period);
    m.end_error = (rows.back().position - points.back()).norm();
    m.longest_rest = longest_rest(rows, m.motion, machine.period);
    m.lines = lines_while_moving(rows, m.motion);
    return m;
}

nlohmann::json report_json(const Measurement& m, const firtp::Program& program, double tsc_hz, const MotionCpu& cpu) {
    const firtp::Measured& d = m.measured;
    nlohmann::json report = {
        {"samples", m.recording.rows.size()},
        {"overruns", m.recording.overruns},
        {"moving_samples", m.samples.size()},
        {"cycle_time_s", d.cycle_time},
        {"max_contour_error_mm", d.max_contour_error},
        {"max_corner_error_mm", d.max_corner_error},
        {"max_path_speed", d.max_path_speed},
        {"end_error_mm", m.end_error},
        {"program_blocks", program.blocks.size()},
        {"tsc_hz", tsc_hz},
        {"motion_controller", stats_json(cpu.controller)},
        {"motion_command_handler", stats_json(cpu.command)},
    };
    report["max_axis_velocity"] = {d.max_velocity[0], d.max_velocity[1], d.max_velocity[2]};
    report["max_axis_acceleration"] = {d.max_acceleration[0], d.max_acceleration[1], d.max_acceleration[2]};
    report["max_axis_jerk"] = {d.max_jerk[0], d.max_jerk[1], d.max_jerk[2]};
    return report;
}

void print_summary(const Measurement& m, const MotionCpu& cpu, const nlohmann::json& report) {
    const firtp::Measured& d = m.measured;
    double max_v = 0.0, max_a = 0.0, max_j = 0.0;
    for (int a = 0; a < 3; ++a) {
        max_v = std::max(max_v, d.max_velocity[a]);
        max_a = std::max(max_a, d.max_acceleration[a]);
        max_j = std::max(max_j, d.max_jerk[a]);
    }
    std::printf("samples      %zu (%zu moving), %ld overruns\n", m.recording.rows.size(), m.samples.size(),
                m.recording.overruns);
    std::printf("cycle time   %.4f s; %zu program lines while moving; longest rest inside %.3f s\n", d.cycle_time,
                m.lines.size(), m.longest_rest);
    std::printf("contour      max error %.4f mm; corners max %.4f mm; end %.3g mm off\n", d.max_contour_error,
                d.max_corner_error, m.end_error);
    std::printf("axes         max velocity %.1f, acceleration %.0f, jerk %.0f (units/s^n, 1 ms differences)\n", max_v,
                max_a, max_j);
    std::printf("cpu          motion-controller median %.1f us, p99 %.1f, max %.1f; motion-command-handler median "
                "%.1f us, p99 %.1f, max %.1f\n",
                cpu.controller.median, cpu.controller.p99, cpu.controller.max, cpu.command.median, cpu.command.p99,
                cpu.command.max);
    if (!report.contains("firtp_tp")) return;
    const auto& t = report["firtp_tp"];
    std::printf("firtp_tp     tpAdd* median %.1f us, max %.1f (%zu adds); tpRunCycle median %.1f us, p99 %.1f, max %.1f; "
                "at most %ld blocks planned in a period\n",
                t["add"]["median_us"].get<double>(), t["add"]["max_us"].get<double>(),
                t["add"]["cycles"].get<std::size_t>(), t["run_cycle"]["median_us"].get<double>(),
                t["run_cycle"]["p99_us"].get<double>(), t["run_cycle"]["max_us"].get<double>(),
                t["most_blocks_planned_in_a_period"].get<long>());
}

bool write_json(const std::string& path, const nlohmann::json& report) {
    std::ofstream out(path);
    out << report.dump(1) << "\n";
    if (out) return true;
    std::cerr << "firtp-tp-check: cannot write " << path << "\n";
    return false;
}

// Measures, checks and reports; the exit status.
int check(const Options& o) {
    Recording recording = read_recording(o.samples_path);
    firtp::MachineConfig machine;
    firtp::Program program;
    try {
        machine = firtp::load_machine(firtp::IniFile::read(o.ini_path));
        program = firtp::read_gcode(o.program_path, machine, recording.rows.front().position);
    } catch (const std::exception& e) {
        std::cerr << "firtp-tp-check: " << e.what() << "\n";
        return 2;
    }
    const Measurement m = measure(std::move(recording), machine, program);
    const double tsc_hz = o.tsc_hz > 0.0 ? o.tsc_hz : measure_tsc_hz();
    const MotionCpu cpu = motion_cpu(m.recording.rows, m.motion, tsc_hz);
    nlohmann::json report = report_json(m, program, tsc_hz, cpu);
    if (!o.tp_samples_path.empty()) report["firtp_tp"] = firtp_tp_report(o.tp_samples_path);
    report["longest_rest_s"] = m.longest_rest;
    report["lines"] = m.lines;
    const std::vector<std::string> failures = check_motion(o, machine, m, report);
    report["failures"] = failures;
    print_summary(m, cpu, report);
    for (const std::string& f : failures) std::printf("FAIL         %s\n", f.c_str());
    if (!o.json_path.empty() && !write_json(o.json_path, report)) return 2;
    return failures.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() == 1 && args[0] == "--version") {
        std::printf("firtp-tp-check %s\n", firtp::version);
        return 0;
    }
    if (args.size() == 1 && args[0] == "--tsc-hz") {
        std::printf("%.0f\n", measure_tsc_hz());
        return 0;
    }
    return check(parse_options(args));
}
