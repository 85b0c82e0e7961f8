#include "plan_options.hpp"

#include "cli_errors.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <sstream>
#include <vector>

namespace firtp::cli {
namespace {

namespace po = boost::program_options;

// Flags that take a value; "--t1 -3" is joined into "--t1=-3" so a negative value reaches
// the validation that names the flag instead of being read as an unknown option "-3".
constexpr const char* valued_flags[] = {"--ini", "--t1", "--t2", "--tolerance", "--period", "--tolerance-meaning",
                                        "--csv", "--json", "--plot", "--lcm-url", "--module", "--max-feed",
                                        "--duration", "--lcm-log", "--modes", "--robust", "--report", "--out",
                                        "--detune"};

}  // namespace

po::options_description machine_flags() {
    po::options_description d("Machine", 100, 50);
    d.add_options()
        ("ini", po::value<std::string>()->value_name("FILE"),
         "LinuxCNC-style INI file describing the machine: [EMCMOT]SERVO_PERIOD, [TRAJ]COORDINATES MAX_LINEAR_VELOCITY, "
         "[AXIS_<L>]MAX_VELOCITY/MAX_ACCELERATION/MAX_JERK, [DISPLAY]MAX_FEED_OVERRIDE, [FIRTP]STAGES T1..T4 "
         "MODES TOLERANCE TOLERANCE_MEANING ARC_CHORD_TOLERANCE RATE_RESERVE MAX_PROGRAM_BLOCKS. Without it: X Y Z at 300 mm/s, 5000 mm/s^2, 100000 mm/s^3, 1 ms period, "
         "every move smoothed at those limits, " FIRTP_DEFAULT_TOLERANCE_TEXT " mm tolerance")
        ("t1", po::value<double>()->value_name("S"), "first FIR stage time T1 in seconds: the paper's fixed chain instead of smoothing at the limits")
        ("t2", po::value<double>()->value_name("S"), "second FIR stage time T2 in seconds (T2 <= T1)")
        ("tolerance", po::value<double>()->value_name("MM"),
         "corner tolerance in mm used by G64 without P (overrides [FIRTP]TOLERANCE)")
        ("period", po::value<double>()->value_name("S"), "servo period in seconds (overrides [EMCMOT]SERVO_PERIOD)")
        ("tolerance-meaning", po::value<std::string>()->value_name("corner|contour"),
         "what the tolerance bounds: corner = closest approach to the programmed corner point (the paper's), "
         "contour = largest distance from the programmed path");
    return d;
}

po::options_description output_flags() {
    po::options_description d("Outputs", 100, 50);
    d.add_options()
        ("csv", po::value<std::string>()->value_name("FILE"),
         "write one row per servo period: t,x,y,z,feed,vx,vy,vz,ax,ay,az,jx,jy,jz,line (mm, s)")
        ("json", po::value<std::string>()->value_name("FILE"),
         "write a report: machine, cycle time (sampled and closed form), every corner (tolerance, "
         "overlap Tk, predicted and measured error) and measured maxima")
        ("plot", po::value<std::string>()->value_name("FILE.png"),
         "draw the XY path, zooms on up to 4 corners, feed and axis accelerations with gnuplot "
         "(Debian package gnuplot-nox)");
    return d;
}

po::options_description mode_flags() {
    po::options_description d("Structural modes", 100, 50);
    d.add_options()
        ("modes", po::value<std::string>()->value_name("LIST"),
         "structural modes the filters are tuned to (T = k / f at the smallest delay), overriding [FIRTP]MODES: "
         "words HZ, HZ/DAMPING or L:HZ/DAMPING (L an axis letter: the mode moves that axis only), e.g. "
         "'X:11.4/0.03 Y:6.8/0.02'; damping 0.02 when not given")
        ("robust", po::value<std::string>()->value_name("NAME"),
         "robust tuning against frequency error, overriding [FIRTP]ROBUST: none (one stage a mode), double (two "
         "stages on the mode), straddle or straddle:SPREAD (zeros at f (1 -+ SPREAD); SPREAD chosen when not "
         "given); see examples/VIBRATION.md");
    return d;
}

namespace {

po::options_description flag_descriptions() {
    po::options_description d("Options", 100, 50);
    d.add_options()("help,h", "show this help and exit");
    d.add(machine_flags()).add(mode_flags()).add(output_flags());
    d.add_options()("report", po::value<std::string>()->value_name("DIR"),
                    "write a self-contained Markdown report into DIR (created if missing): report.md with the "
                    "machine, path, feed, axis kinematics, corner errors and acceleration spectrum, their PNGs "
                    "(gnuplot), and with structural modes the vibration table of `firtp simulate`");
    return d;
}

std::vector<std::string> join_negative_values(std::span<const std::string> args) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool valued = std::find(std::begin(valued_flags), std::end(valued_flags), args[i]) != std::end(valued_flags);
        if (valued && i + 1 < args.size() && args[i + 1].starts_with("-") && args[i + 1] != "--") {
            out.push_back(args[i] + "=" + args[i + 1]);
            ++i;
        } else {
            out.push_back(args[i]);
        }
    }
    return out;
}

ToleranceMeaning parse_meaning(const std::string& text) {
    if (const std::optional<ToleranceMeaning> meaning = parse_tolerance_meaning(text)) return *meaning;
    throw UsageError("--tolerance-meaning: '" + text + "' must be corner or contour");
}

template <class T>
std::optional<T> optional_value(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return std::nullopt;
    return vm[name].as<T>();
}

}  // namespace

po::variables_map parse_flags(std::span<const std::string> args, const po::options_description& flags,
                             const std::string& command, bool takes_program) {
    po::options_description all = flags;
    po::positional_options_description positional;
    if (takes_program) {
        all.add_options()("program", po::value<std::string>(), "G-code program");
        positional.add("program", 1);
    }
    po::variables_map vm;
    try {
        const auto style = po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
        po::store(po::command_line_parser(join_negative_values(args))
                      .options(all)
                      .positional(positional)
                      .style(style)
                      .run(),
                  vm);
        po::notify(vm);
    } catch (const po::error& e) {
        throw UsageError(std::string(e.what()) + " (see firtp " + command + " --help)");
    }
    if (takes_program && !vm.count("help") && !vm.count("program"))
        throw UsageError(command + ": missing PROGRAM.ngc (see firtp " + command + " --help)");
    return vm;
}

void read_machine_flags(const po::variables_map& vm, PlanOptions& o) {
    o.help = vm.count("help") > 0;
    if (vm.count("program")) o.program = vm["program"].as<std::string>();
    if (const auto s = optional_value<std::string>(vm, "ini")) o.ini = *s;
    o.overrides.t1 = optional_value<double>(vm, "t1");
    o.overrides.t2 = optional_value<double>(vm, "t2");
    o.overrides.tolerance = optional_value<double>(vm, "tolerance");
    o.overrides.period = optional_value<double>(vm, "period");
    if (const auto s = optional_value<std::string>(vm, "tolerance-meaning")) o.tolerance_meaning = parse_meaning(*s);
}

void read_output_flags(const po::variables_map& vm, PlanOptions& o) {
    if (const auto s = optional_value<std::string>(vm, "csv")) o.csv = *s;
    if (const auto s = optional_value<std::string>(vm, "json")) o.json = *s;
    if (const auto s = optional_value<std::string>(vm, "plot")) o.plot = *s;
}

void read_mode_flags(const po::variables_map& vm, PlanOptions& o) {
    o.modes = optional_value<std::string>(vm, "modes");
    o.robust = optional_value<std::string>(vm, "robust");
}

PlanOptions parse_plan_options(std::span<const std::string> args) {
    const po::variables_map vm = parse_flags(args, flag_descriptions(), "plan", true);
    PlanOptions o;
    read_machine_flags(vm, o);
    read_mode_flags(vm, o);
    read_output_flags(vm, o);
    if (const auto s = optional_value<std::string>(vm, "report")) o.report = *s;
    return o;
}

std::string plan_help() {
    std::ostringstream text;
    text << "Usage: firtp plan PROGRAM.ngc [options]\n\n"
            "Plans a G-code program (G0/G1, G2/G3 arcs in G17/G18/G19, X Y Z A B C U V W, G61/G61.1 exact\n"
            "stop, G64 P tolerance) with FIR-filter corner smoothing, samples it every servo period, measures\n"
            "it against the programmed path and prints a summary. Output files are written only when\n"
            "everything succeeded.\n\n"
         << flag_descriptions()
         << "\nExit status: 0 success, 1 bad program/INI/output/gnuplot, 2 bad command line.\n"
            "\nExamples:\n  firtp plan examples/diamond.ngc --t1 0.148 --t2 0.089 --csv out.csv --json out.json"
            " --plot out.png\n  firtp plan examples/diamond.ngc --ini examples/diamond_modes.ini --report report\n";
    return text.str();
}

}  // namespace firtp::cli
