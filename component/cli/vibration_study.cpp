#include "vibration_study.hpp"

#include "number_text.hpp"

#include <firtp/gcode.hpp>
#include <firtp/reference_planner.hpp>
#include <firtp/text_cat.hpp>
#include <firtp/trajectory.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace firtp::cli {
namespace {

constexpr double min_settle = 0.5;      // s of rest simulated after a motion
constexpr double settle_periods = 4.0;  // ... or this many periods of the slowest mode

std::string times_text(const FilterTimes& f) {
    std::string text = "T = ";
    for (int i = 0; i < f.stages; ++i) text += cat(i ? ", " : "", fixed_text(f.T[i] * 1e3, 3));
    return cat(text, " ms (Td ", fixed_text(f.delay() * 1e3, 3), " ms)");
}

// The machine without modes; stages dropped from the end while one cannot be derived.
MachineConfig untuned_machine(const MachineConfig& machine, std::string& note) {
    MachineConfig m = machine;
    m.tuning = ModeTuning{};
    for (;;) {
        try {
            m.filter_times();
            note = m.stages == machine.stages ? "the same machine without modes"
                                              : cat("the same machine without modes, ", std::to_string(m.stages),
                                                    " stage(s): no limit gives the others");
            return m;
        } catch (const ConfigError&) {
            if (m.stages == 1) throw;
            --m.stages;
        }
    }
}

Trajectory plan_program(const MachineConfig& machine, const Program& program) {
    try {
        return plan_trajectory(machine.planner_parameters(), program.start, program.blocks);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(program.file + ": " + e.what());
    }
}

void settle(std::vector<AxisState>& samples, double period, double seconds) {
    if (samples.empty()) return;
    AxisState rest = samples.back();
    rest.velocity.setZero();
    rest.acceleration.setZero();
    rest.jerk.setZero();
    const auto extra = static_cast<std::size_t>(std::ceil(seconds / period));
    const double t0 = rest.time;
    for (std::size_t k = 1; k <= extra; ++k) {
        rest.time = t0 + static_cast<double>(k) * period;
        samples.push_back(rest);
    }
}

bool axis_moves(const std::vector<AxisState>& samples, int axis) {
    return std::any_of(samples.begin(), samples.end(),
                       [&](const AxisState& s) { return s.velocity[static_cast<Eigen::Index>(axis)] != 0.0; });
}

std::vector<PlantMode> plant_modes(const MachineConfig& machine, const std::vector<AxisState>& samples, double detune) {
    std::vector<PlantMode> plant;
    const auto add = [&](int axis, const StructuralMode& m) {
        for (const PlantMode& p : plant)
            if (p.axis == axis && p.tuned_hz == m.frequency_hz) return;
        plant.push_back({axis, m.frequency_hz, m.frequency_hz * (1.0 + detune), m.damping});
    };
    for (const StructuralMode& m : machine.tuning.modes) {
        if (m.axis >= 0) add(m.axis, m);
        else
            for (int a = 0; a < machine.limits.axes; ++a)
                if (axis_moves(samples, a)) add(a, m);
    }
    return plant;
}

}  // namespace

std::string plant_name(const PlantMode& mode) {
    return cat(std::string(1, axis_letters[mode.axis]), " ", fixed_text(mode.frequency_hz, 2),
               " Hz");
}

VibrationStudy study_vibration(const MachineConfig& machine, const std::filesystem::path& program, double detune) {
    if (machine.tuning.modes.empty())
        throw ConfigError("no structural modes to simulate: give [FIRTP]MODES in the INI or --modes");
    if (!(std::isfinite(detune) && detune > -0.9 && detune < 10.0))
        throw ConfigError("the detuning must lie between -0.9 and 10 (a share of the frequency)");
    VibrationStudy study;
    study.program = program.filename().string();
    study.period = machine.period;
    study.detune = detune;
    study.tuned = machine.tuned_filters();
    const MachineConfig untuned = untuned_machine(machine, study.untuned_note);
    study.untuned = untuned.filter_times();

    const Program tuned_program = read_gcode(program, machine);
    const Program untuned_program = read_gcode(program, untuned);

    PlannerCase tuned_case{"firtp tuned", times_text(study.tuned.filters), study.tuned.filters.delay(), 0.0,
                           plan_program(machine, tuned_program).samples, {}};
    PlannerCase untuned_case{"firtp untuned", times_text(study.untuned), study.untuned.delay(), 0.0,
                             plan_program(untuned, untuned_program).samples, {}};
    // The S-curve keeps what firtp's plan keeps (the rate reserve included).
    const MachineLimits limits = planned_limits(untuned.planner_parameters());
    PlannerCase reference{"S-curve, exact stop", "jerk-limited S-curve per block, stop at every block", 0.0, 0.0,
                          plan_exact_stop_scurves(limits, machine.period, untuned_program.start, untuned_program.blocks),
                          {}};

    study.plant = plant_modes(machine, tuned_case.samples, detune);
    if (study.plant.empty()) throw ConfigError("the program moves no axis that carries a mode");
    double slowest = study.plant.front().frequency_hz;
    for (const PlantMode& p : study.plant) slowest = std::min(slowest, p.frequency_hz);
    study.settle = std::max(min_settle, settle_periods / slowest);

    for (const PlantMode& p : study.plant)
        study.bands.push_back({vibration_band(study.tuned.filters, &study.untuned, p.tuned_hz, p.damping),
                               vibration_band(study.tuned.filters, nullptr, p.tuned_hz, p.damping)});

    for (const RobustTuning robust : {RobustTuning::none, RobustTuning::double_stage, RobustTuning::straddle}) {
        MachineConfig option = machine;
        option.tuning.robust = robust;
        option.tuning.spread = robust == machine.tuning.robust ? machine.tuning.spread : 0.0;
        TunedFilters chain;
        try {
            chain = option.tuned_filters();
        } catch (const ConfigError&) {
            continue;  // more stages than the chain has
        }
        RobustOption o{robust == RobustTuning::none ? "none" : robust == RobustTuning::double_stage ? "double" : "straddle",
                       chain.filters, {}};
        if (robust == RobustTuning::straddle) {
            std::string spreads;
            for (const double d : chain.spreads) spreads += cat(spreads.empty() ? " " : "/", fixed_text(d, 3));
            o.name += spreads;
        }
        for (const PlantMode& p : study.plant)
            o.bands.push_back({vibration_band(chain.filters, &study.untuned, p.tuned_hz, p.damping),
                               vibration_band(chain.filters, nullptr, p.tuned_hz, p.damping)});
        study.options.push_back(std::move(o));
    }

    study.cases = {std::move(tuned_case), std::move(untuned_case), std::move(reference)};
    for (PlannerCase& c : study.cases) {
        c.cycle_time = c.samples.empty() ? 0.0 : c.samples.back().time;
        settle(c.samples, study.period, study.settle);
        for (const PlantMode& p : study.plant)
            c.responses.push_back(simulate_mode(c.samples, p.axis, p.frequency_hz, p.damping, study.period));
    }
    return study;
}

}  // namespace firtp::cli
