// One program on one machine planned three ways, each driving the machine's structural modes:
// firtp tuned to the modes, firtp with the same limits but untuned filters, and a plain
// exact-stop S-curve planner (component/analysis reference_planner.hpp).
#pragma once

#include <firtp/machine.hpp>
#include <firtp/mode_response.hpp>
#include <firtp/mode_tuning.hpp>
#include <firtp/types.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace firtp::cli {

// A mode as the simulated machine has it: on one axis, possibly off the frequency tuned to.
struct PlantMode {
    int axis = 0;
    double tuned_hz = 0.0;      // what the filters were tuned to
    double frequency_hz = 0.0;  // the plant's: tuned_hz (1 + detune)
    double damping = 0.0;
};

struct PlannerCase {
    std::string name;                     // "firtp tuned", "firtp untuned", "S-curve, exact stop"
    std::string filters;                  // how it shapes the motion, for people
    double delay = 0.0;                   // Td of its chain (0 for the S-curve)
    double cycle_time = 0.0;              // motion only
    std::vector<AxisState> samples;       // the motion, then at rest until `settle` after it
    std::vector<ModeResponse> responses;  // one per VibrationStudy::plant entry
};

// The tuned chain's band of frequency error (FrequencyBand, mode_tuning.hpp) at one mode.
struct ModeBands {
    FrequencyBand vs_untuned;     // residual <= 5 % of the untuned chain's
    FrequencyBand vs_unfiltered;  // residual <= 5 % of an unfiltered step's (input-shaper tables)
};

// One robust option on the same machine: its chain and its bands at each plant mode.
struct RobustOption {
    std::string name;              // "none", "double", "straddle 0.255"
    FilterTimes filters;
    std::vector<ModeBands> bands;  // per plant entry
};

struct VibrationStudy {
    std::string program;            // file name
    double period = 0.0;
    double detune = 0.0;
    double settle = 0.0;            // rest simulated after each motion, s
    TunedFilters tuned;             // the tuned machine's chain and what each stage serves
    FilterTimes untuned;            // the same machine without modes
    std::string untuned_note;       // how the untuned chain was derived
    std::vector<PlantMode> plant;
    std::vector<ModeBands> bands;   // per plant entry
    std::vector<PlannerCase> cases; // tuned, untuned, S-curve
    std::vector<RobustOption> options;  // none, double, straddle (auto spread), where the stages suffice
};

// `machine` must list modes. Modes given for every axis are simulated on each axis that moves.
// The untuned chain is the machine's without modes (given times or v/a, a/j); when a stage is then
// not derivable (no jerk limit) the chain keeps the stages that are. Throws ConfigError (no modes,
// nothing untuned), GcodeError or std::runtime_error.
VibrationStudy study_vibration(const MachineConfig& machine, const std::filesystem::path& program, double detune);

// "X 11.40 Hz" for a plant mode.
std::string plant_name(const PlantMode& mode);

}  // namespace firtp::cli
