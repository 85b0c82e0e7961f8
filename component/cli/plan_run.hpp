// One planned program: machine, blocks, sampled trajectory and what was measured on it.
#pragma once

#include "plan_options.hpp"

#include <firtp/gcode.hpp>
#include <firtp/machine.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <optional>
#include <vector>

namespace firtp::cli {

struct PlanRun {
    MachineConfig machine;
    PlannerParameters parameters;
    Program program;
    Trajectory trajectory;
    std::vector<AxisVector> points;  // start, then the end of every block that moves
    Measured measured;
    std::vector<std::optional<double>> corner_errors;  // measured, one per trajectory.corners entry
    double closed_form_cycle_time = 0.0;  // the paper's fixed chain: sum(Tv) + sum(Td - Tk) + Td
    double feed_time = 0.0;               // sum(Tv): every block at its programmed feed, no corners
};

// The machine: INI or built-in, then the flag overrides (UsageError names a bad flag).
MachineConfig load_machine_config(const PlanOptions& options);

// Loads the machine (INI or built-in, then overrides), reads and plans the program, measures it.
// Throws UsageError for bad flag values, ConfigError / GcodeError / std::runtime_error otherwise.
PlanRun run_plan(const PlanOptions& options);

// Measures run.trajectory.samples against run.program (points, maxima, corner errors, closed form).
void measure_plan(PlanRun& run);

}  // namespace firtp::cli
