// firtp: command-line front end of the FIR-filter trajectory planner. Dispatches subcommands and
// turns errors into "firtp: <what>" on stderr with exit status 1 (input) or 2 (usage); plan and run
// exit 3 when the measurement finds a tolerance or a limit broken (plan_checks.hpp).
#include "cli_errors.hpp"
#include "plan_command.hpp"
#include "record_command.hpp"
#include "run_command.hpp"
#include "simulate_command.hpp"
#include <firtp/version.hpp>

#include <exception>
#include <span>
#include <iostream>
#include <string>
#include <vector>

namespace {

constexpr const char* usage =
    "Usage: firtp COMMAND [options]\n\n"
    "FIR-filter kinematic corner smoothing (Sencer, Ishizaki, Shamoto, CIRP Annals 2015).\n\n"
    "Commands:\n"
    "  plan PROGRAM.ngc   plan a G-code program; print a summary, optionally write\n"
    "                     --csv FILE, --json FILE and --plot FILE.png\n"
    "  run PROGRAM.ngc    the whole chain in this process: host stub -> LCM -> bridge -> HAL\n"
    "                     component on a hal-shim servo thread -> axis states over LCM; same outputs\n"
    "  serve              the HAL component and its LCM bridge on a real-time servo thread\n"
    "  host PROGRAM.ngc   stream a program over LCM to `firtp serve`, with progress and keys\n"
    "  simulate PROGRAM.ngc  firtp tuned to the structural modes, untuned, and an S-curve planner\n"
    "                     driving the modes: residual vibration table, --out DIR for plots\n"
    "  record LOG.lcmlog  record every LCM message without loss, checking every stream's seq numbers\n"
    "  replay LOG.lcmlog  run the component again on a recorded log and compare its axis states\n\n"
    "Options:\n"
    "  -h, --help         show this help and exit\n"
    "  --version          print firtp's version and exit\n\n"
    "Run 'firtp COMMAND --help' for a command's options (plan: --ini, --t1, --t2, --tolerance,\n"
    "--period, --tolerance-meaning, --csv, --json, --plot; run, serve, host add --lcm-url).\n\n"
    "Exit status: 0 done; 1 bad input (program, INI, files); 2 bad command line; 3 plan and run:\n"
    "the measured trajectory breaks a tolerance, an axis limit or the end point (named on stderr);\n"
    "4 record: messages were lost; replay: the axis states differ from the recorded ones.\n";

int dispatch(const std::vector<std::string>& args) {
    if (args.empty()) {
        std::cerr << usage;
        return firtp::cli::exit_usage_error;
    }
    if (args[0] == "--version") {
        std::cout << "firtp " << firtp::version << "\n";
        return 0;
    }
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::cout << usage;
        return 0;
    }
    if (args[0] == "plan") return firtp::cli::plan_command(std::span(args).subspan(1));
    if (args[0] == "run") return firtp::cli::run_command(std::span(args).subspan(1));
    if (args[0] == "serve") return firtp::cli::serve_command(std::span(args).subspan(1));
    if (args[0] == "host") return firtp::cli::host_command(std::span(args).subspan(1));
    if (args[0] == "simulate") return firtp::cli::simulate_command(std::span(args).subspan(1));
    if (args[0] == "record") return firtp::cli::record_command(std::span(args).subspan(1));
    if (args[0] == "replay") return firtp::cli::replay_command(std::span(args).subspan(1));
    throw firtp::cli::UsageError("unknown command '" + args[0] + "' (see firtp --help)");
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return dispatch(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const firtp::cli::UsageError& e) {
        std::cerr << "firtp: " << e.what() << "\n";
        return firtp::cli::exit_usage_error;
    } catch (const std::exception& e) {
        std::cerr << "firtp: " << e.what() << "\n";
        return firtp::cli::exit_input_error;
    }
}
