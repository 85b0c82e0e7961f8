#include "simulate_command.hpp"

#include "cli_errors.hpp"
#include "gnuplot_pipe.hpp"
#include "output_files.hpp"
#include "plan_run.hpp"
#include "report.hpp"
#include "simulate_options.hpp"
#include "vibration_plot.hpp"
#include "vibration_study.hpp"
#include "vibration_table.hpp"

#include <firtp/text_cat.hpp>

#include <cmath>
#include <iostream>
#include <stdexcept>

namespace firtp::cli {
namespace {

std::vector<std::filesystem::path> write_files(const VibrationStudy& study, const std::filesystem::path& dir,
                                               const std::filesystem::path& gnuplot) {
    make_output_directory(dir);
    OutputFiles outputs;
    const std::vector<std::filesystem::path> files{dir / "vibration.md", dir / "vibration.json", dir / "response.png",
                                                   dir / "spectrum.png"};
    outputs.write(files[0], [&](std::ostream& out) {
        out << "# Vibration: " << study.program << "\n\n"
            << vibration_markdown(study, "##") << "\n![mode deflection](response.png)\n\n![spectra](spectrum.png)\n";
    });
    outputs.write(files[1], [&](std::ostream& out) { out << vibration_json(study).dump(2) << "\n"; });
    run_gnuplot(gnuplot, response_plot_script(study, outputs.create(files[2])));
    run_gnuplot(gnuplot, spectrum_plot_script(study_spectrum(study), outputs.create(files[3])));
    outputs.commit();
    return files;
}

}  // namespace

int simulate_command(std::span<const std::string> args) {
    const SimulateOptions options = parse_simulate_options(args);
    if (options.plan.help) {
        std::cout << simulate_help();
        return 0;
    }
    if (!(std::isfinite(options.detune) && options.detune > -0.9 && options.detune < 10.0))
        throw UsageError("--detune: must lie between -0.9 and 10 (a share of the mode frequency)");
    const std::optional<std::filesystem::path> gnuplot = options.out ? std::optional(find_gnuplot()) : std::nullopt;
    const MachineConfig machine = load_machine_config(options.plan);
    const VibrationStudy study = study_vibration(machine, options.plan.program, options.detune);
    std::vector<std::filesystem::path> written =
        options.out ? write_files(study, *options.out, *gnuplot) : std::vector<std::filesystem::path>{};
    if (options.json) {
        OutputFiles outputs;
        outputs.write(*options.json, [&](std::ostream& out) { out << vibration_json(study).dump(2) << "\n"; });
        outputs.commit();
        written.push_back(*options.json);
    }
    print_vibration(std::cout, study);
    for (const auto& path : written) std::cout << "wrote        " << path.string() << "\n";
    return 0;
}

}  // namespace firtp::cli
