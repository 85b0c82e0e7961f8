#include "simulate_options.hpp"

#include "cli_errors.hpp"

#include <boost/program_options.hpp>

#include <sstream>

namespace firtp::cli {
namespace {

namespace po = boost::program_options;

po::options_description simulate_flags() {
    po::options_description d("Options", 100, 50);
    d.add_options()("help,h", "show this help and exit");
    d.add(machine_flags()).add(mode_flags());
    po::options_description sim("Simulation", 100, 50);
    sim.add_options()
        ("detune", po::value<double>()->value_name("E"),
         "the machine's modes sit at f (1 + E) while the filters stay tuned to f (frequency error, e.g. -0.1)")
        ("out", po::value<std::string>()->value_name("DIR"),
         "write DIR/vibration.md (the tables), DIR/vibration.json (every figure, every stop), "
         "DIR/response.png (mode deflection against time) and DIR/spectrum.png (acceleration spectra, the "
         "chains' magnitude, the modes marked); DIR is created if missing; the PNGs need gnuplot")
        ("json", po::value<std::string>()->value_name("FILE"),
         "write every figure (filters, each mode under each planner, every stop, bands, robust options) as JSON, "
         "as DIR/vibration.json holds it");
    d.add(sim);
    return d;
}

}  // namespace

SimulateOptions parse_simulate_options(std::span<const std::string> args) {
    const po::variables_map vm = parse_flags(args, simulate_flags(), "simulate", true);
    SimulateOptions o;
    read_machine_flags(vm, o.plan);
    read_mode_flags(vm, o.plan);
    if (vm.count("detune")) o.detune = vm["detune"].as<double>();
    if (vm.count("out")) o.out = vm["out"].as<std::string>();
    if (vm.count("json")) o.json = vm["json"].as<std::string>();
    return o;
}

std::string simulate_help() {
    std::ostringstream text;
    text << "Usage: firtp simulate PROGRAM.ngc [options]\n\n"
            "Plans the program three ways on the same machine and limits: firtp with its filters tuned to the\n"
            "machine's structural modes ([FIRTP]MODES or --modes), firtp untuned (the same machine without\n"
            "modes), and a plain jerk-limited S-curve planner that stops at every block. Each mode, a lightly\n"
            "damped oscillator x'' + 2 zeta w x' + w^2 x = -a_axis(t) on its axis, is driven by the planned\n"
            "acceleration (exact per servo period) and the residual vibration after every stop, the\n"
            "vibration while moving and the lag are reported, with the tuned chain's band of frequency error\n"
            "(within 5 % of untuned) and the delay it costs. See examples/VIBRATION.md.\n\n"
         << simulate_flags()
         << "\nExit status: 0 success, 1 bad program/INI/output/gnuplot, 2 bad command line.\n"
            "\nExample:\n  firtp simulate examples/diamond.ngc --ini examples/diamond_modes.ini --out vibration\n";
    return text.str();
}

}  // namespace firtp::cli
