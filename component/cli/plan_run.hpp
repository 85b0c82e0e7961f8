// One planned program: machine, blocks, sampled trajectory and what was measured on it.
#pragma once

#include "corner_list.hpp"
#include "path_points.hpp"
#include "plan_options.hpp"
#include "program_spool.hpp"

#include <firtp/gcode.hpp>
#include <firtp/machine.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace firtp::cli {

struct PlanRun {
    MachineConfig machine;
    PlannerParameters parameters;
    Program program;                 // its blocks only when not spooled
    std::shared_ptr<ProgramSpool> spool;  // the blocks, read back as the planner takes them (plan)
    std::size_t blocks = 0;          // blocks read, moving or not
    Trajectory trajectory;           // samples only where kept (--report, run's reference)
    std::size_t sample_count = 0;    // samples planned (or received), kept or not
    PathPoints points;               // start, then the end of every block that moves
    Measured measured;
    CornerList corners;              // the planner's reports and their measured errors
    double closed_form_cycle_time = 0.0;  // the paper's fixed chain: sum(Tv) + sum(Td - Tk) + Td
    double feed_time = 0.0;               // sum(Tv): every block at its programmed feed, no corners
};

// The machine: INI or built-in, then the flag overrides (UsageError names a bad flag).
MachineConfig load_machine_config(const PlanOptions& options);

// Loads the machine (INI or built-in, then overrides) and reads the program: everything but the
// plan. Throws UsageError for bad flag values, ConfigError / GcodeError otherwise.
PlanRun prepare_plan(const PlanOptions& options);
// Reads a program through LinuxCNC's interpreter into a ProgramSpool, closed (throws GcodeError).
std::shared_ptr<ProgramSpool> spool_program(const std::filesystem::path& file, const MachineConfig& machine,
                                            const AxisVector& start);
// The same with the blocks in a ProgramSpool, not in memory: for a plan that streams.
PlanRun prepare_spooled_plan(const PlanOptions& options);

// Plans run.program (or run.spool), handing every sample and corner report to `sink` as it is made; sets
// run.trajectory's cycle time and stats and run.sample_count. Throws std::runtime_error naming the
// file and line of an invalid block.
void plan_program(PlanRun& run, TrajectorySink& sink);

// prepare_plan, then the plan keeping every sample, measured (measure_plan).
PlanRun run_plan(const PlanOptions& options);

// Measures run.trajectory.samples against run.program (maxima, corner errors, closed form).
void measure_plan(PlanRun& run);

// What a measurement of the samples gives the run: run.measured, the corner errors paired with
// the corner reports, the closed form.
void take_measurement(PlanRun& run, Measured measured);

}  // namespace firtp::cli
