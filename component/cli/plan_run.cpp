#include "plan_run.hpp"

#include "cli_errors.hpp"

#include <stdexcept>
#include <string>

namespace firtp::cli {

MachineConfig load_machine_config(const PlanOptions& options) {
    MachineConfig machine = options.ini ? load_machine(IniFile::read(*options.ini)) : default_machine();
    try {
        apply_overrides(machine, options.overrides);
    } catch (const ConfigError& e) {
        throw UsageError(e.what());  // names the flag
    }
    if (options.tolerance_meaning) machine.tolerance_meaning = *options.tolerance_meaning;
    try {
        if (options.modes) machine.tuning.modes = parse_modes(*options.modes, machine.limits.axes);
    } catch (const ConfigError& e) {
        throw UsageError(std::string("--modes: ") + e.what());
    }
    try {
        if (options.robust) parse_robust(*options.robust, machine.tuning);
    } catch (const ConfigError& e) {
        throw UsageError(std::string("--robust: ") + e.what());
    }
    return machine;
}

namespace {

// Points of the path and the total pulse width sum(Tv) over the blocks that move.
std::vector<AxisVector> moving_points(const Program& program, double& tv_sum) {
    std::vector<AxisVector> points{program.start};
    tv_sum = 0.0;
    for (const Block& block : program.blocks) {
        const double length = (block.target - points.back()).norm();
        if (length < min_block_length) continue;  // skipped by the planner too
        tv_sum += length / block.feed;
        points.push_back(block.target);
    }
    return points;
}

}  // namespace

PlanRun prepare_plan(const PlanOptions& options) {
    PlanRun run;
    run.machine = load_machine_config(options);
    run.parameters = run.machine.planner_parameters();
    run.program = read_gcode(options.program, run.machine);
    run.blocks = run.program.blocks.size();
    run.points = moving_points(run.program, run.feed_time);
    run.trajectory.start = run.program.start;
    return run;
}

std::shared_ptr<ProgramSpool> spool_program(const std::filesystem::path& file, const MachineConfig& machine,
                                            const AxisVector& start) {
    auto spool = std::make_shared<ProgramSpool>(start);
    read_gcode(file, machine, start, *spool);
    spool->close();
    return spool;
}

PlanRun prepare_spooled_plan(const PlanOptions& options) {
    PlanRun run;
    run.machine = load_machine_config(options);
    run.parameters = run.machine.planner_parameters();
    run.program.file = options.program.string();
    auto spool = spool_program(options.program, run.machine, run.program.start);
    run.program.events = std::move(spool->events());
    run.program.joined = spool->joined();
    run.blocks = spool->blocks();
    run.feed_time = spool->feed_time();
    run.points = PathPoints(std::shared_ptr<const ProgramSpool>(spool));
    run.corners.spool();
    run.spool = std::move(spool);
    run.trajectory.start = run.program.start;
    return run;
}

void plan_program(PlanRun& run, TrajectorySink& sink) {
    try {
        const StreamedTrajectory streamed =
            run.spool ? plan_trajectory(run.parameters, run.program.start, *run.spool->read_blocks(), sink)
                      : plan_trajectory(run.parameters, run.program.start, run.program.blocks, sink);
        run.trajectory.cycle_time = streamed.cycle_time;
        run.trajectory.stats = streamed.stats;
        run.sample_count = streamed.samples;
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(run.program.file + ": " + e.what());
    }
}

PlanRun run_plan(const PlanOptions& options) {
    PlanRun run = prepare_plan(options);
    struct Keep : TrajectorySink {
        Trajectory& t;
        void sample(const AxisState& state) override { t.samples.push_back(state); }
        CornerList& corners;
        Keep(Trajectory& into, CornerList& c) : t(into), corners(c) {}
        void corner(const CornerReport& report) override { corners.push_back(report); }
    } keep(run.trajectory, run.corners);
    plan_program(run, keep);
    measure_plan(run);
    return run;
}

void measure_plan(PlanRun& run) {
    run.sample_count = run.trajectory.samples.size();
    take_measurement(run, measure(run.trajectory.samples, run.points.kept(), run.parameters.period));
}

void take_measurement(PlanRun& run, Measured measured) {
    run.measured = std::move(measured);
    if (run.sample_count > 0) run.trajectory.cycle_time = run.measured.cycle_time;

    // Interior points and corners are the same junctions, in order, when both skipped the same blocks.
    // A streamed measurement gave its errors to run.corners as it went, a batch one has them here.
    auto& corners = run.corners;
    if (corners.errors_count() == 0)
        for (const double e : run.measured.corner_errors) corners.add_error(e);
    corners.pair_errors();

    run.closed_form_cycle_time = 0.0;
    if (run.parameters.fixed_chain && run.points.size() > 1) {
        const double td = run.parameters.filters.delay();
        double gaps = 0.0;
        for (const CornerReport& c : corners) gaps += td - c.Tk;
        run.closed_form_cycle_time = run.feed_time + gaps + td;
    }
}

}  // namespace firtp::cli
