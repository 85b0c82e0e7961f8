// Filter times tuned to a machine's structural modes, and how much vibration a chain leaves in a
// lightly damped mode (Sencer et al. 2015, Eq. 8-10; residual vibration as input-shaper work
// defines it, e.g. Singer and Seering 1990, Klipper's shaper tables).
//
// A moving average of length T has |M(jw)| = |sin(w T / 2) / (w T / 2)| (Eq. 9): zeros at
// f = k / T. A stage with T = k / f therefore keeps a mode at f out of the motion (Eq. 10). The
// chain's magnitude is the product over its stages, so one stage per mode suffices and the other
// stages only attenuate further.
//
// Residual vibration V: a mode x'' + 2 zeta w x' + w^2 x = -a(t) driven by the chain's response
// to a velocity step, measured once the response is over, as a share of what the unfiltered step
// (an acceleration impulse) leaves. For one stage, with s = zeta w - j w_d:
//     V_i = |1 - exp(-s T_i)| / (T_i |s|),   V = prod V_i  (each V_i <= 1),
// which is |sinc(w T_i / 2)| when zeta = 0. Every stop and every velocity change of a block is
// such a step, so V is the share of vibration that survives any motion the chain produces.
#pragma once

#include <firtp/parameters.hpp>

#include <array>
#include <span>
#include <vector>

namespace firtp {

// Damping assumed when a mode is given by its frequency alone: lightly damped steel structure.
constexpr double default_mode_damping = 0.02;

// The vibration budget of the robust bands: 5 % of the reference (a 20x reduction).
constexpr double default_vibration_threshold = 0.05;

struct StructuralMode {
    double frequency_hz = 0.0;              // undamped natural frequency f
    double damping = default_mode_damping;  // zeta, 0 <= zeta < 1
    int axis = -1;                          // axis index (X = 0) it moves, -1: every axis
};

// How many stages a mode takes and where their zeros sit.
enum class RobustTuning {
    none,          // one stage, T = k / f: the narrowest band, the shortest delay
    double_stage,  // two stages, both T = k / f: a double zero on f
    straddle,      // two stages with zeros at f (1 - spread) and f (1 + spread)
};

struct ModeTuning {
    std::vector<StructuralMode> modes;
    RobustTuning robust = RobustTuning::none;
    double spread = 0.0;  // straddle: 0 < spread < 0.5; 0 = straddle_spread(zeta) per mode
};

// Stages a tuning needs: one per distinct mode, two with a robust option.
int tuned_stage_count(const ModeTuning& tuning);

// The modes the chain is tuned to: equal frequencies (relative 1e-9) on several axes count once,
// with the smallest damping. Throws std::invalid_argument for a frequency that is not positive and
// finite or a damping outside [0, 1).
std::vector<StructuralMode> distinct_modes(std::span<const StructuralMode> modes);

// One stage of a tuned chain.
struct TunedStage {
    double time = 0.0;   // T, s
    int mode = -1;       // index into distinct_modes(), -1: the stage only keeps the axis limits
    int k = 0;           // T = k / zero_hz
    double zero_hz = 0;  // the zero placed on (or beside) the mode: f, f (1 - spread) or f (1 + spread)
};

struct TunedFilters {
    FilterTimes filters;                            // T1 >= T2 >= ... (the planner's)
    std::array<TunedStage, max_stages> stages{};    // the same stages, same order
    std::vector<StructuralMode> modes;              // distinct_modes(tuning.modes)
    std::vector<double> spreads;                    // per mode, the straddle spread used (0 otherwise)
};

// Stage times for a chain of at least `stages` stages (more when the modes need them) such that
// - every mode has its stage(s) with T = k / zero (k >= 1 whole), so the chain is zero on the mode;
// - sorted T1 >= T2 >= ..., the i-th largest time is at least the i-th largest lower bound
//   (lower_bounds: T1 >= max v/a and T2 >= max a/j over the axes, or given times; 0 = none), so the
//   axis limits hold as they do untuned;
// - among all assignments of modes to stages and all k, the delay Td = sum T_i is the smallest
//   (every stop costs Td, every corner Td - Tk).
// Throws std::invalid_argument when more than 4 stages are needed, a stage has neither a mode nor a
// positive bound, a mode or spread is out of range, or the bounds need a stage of more than 10^6
// periods of its mode (or a delay that is not finite): any finite input, however large or small.
TunedFilters tune_filters(std::span<const double> lower_bounds, int stages, const ModeTuning& tuning);

// tune_filters over limit_filter_times(limits, given) (parameters.hpp): what [FIRTP]MODES gives.
TunedFilters tune_filter_times(const MachineLimits& limits, int stages, std::span<const double> given,
                               const ModeTuning& tuning);

// |M(j 2 pi f)| = prod |sin(pi f T_i) / (pi f T_i)| (Eq. 8-9).
double chain_magnitude(const FilterTimes& filters, double frequency_hz);

// V of one stage and of the chain (see the top of this file).
double stage_residual_vibration(double T, double frequency_hz, double damping);
double residual_vibration(const FilterTimes& filters, double frequency_hz, double damping);

// Frequency errors e (true frequency = f (1 + e)) over which a tuned chain keeps the residual
// vibration at most `threshold` times the reference's: the unfiltered step (reference nullptr, the
// convention of input-shaper tables) or another chain (e.g. the untuned one). The band is the
// interval around e = 0 searched over -0.9 <= e <= max_error; empty when e = 0 already fails.
struct FrequencyBand {
    bool empty = true;
    double low = 0.0;          // <= 0
    double high = 0.0;         // >= 0
    bool open_above = false;   // still within the threshold at e = max_error
};
FrequencyBand vibration_band(const FilterTimes& tuned, const FilterTimes* reference, double frequency_hz,
                             double damping, double threshold = default_vibration_threshold,
                             double max_error = 1.0);

// The straddle spread that widens the band of a straddled pair alone (reference: the unfiltered
// step) the most at this damping and threshold; searched over 0.01 ... 0.45.
double straddle_spread(double damping, double threshold = default_vibration_threshold);

// The stages of one mode alone, k = 1: what the band tables quote per option.
FilterTimes mode_stages(const StructuralMode& mode, RobustTuning robust, double spread);

}  // namespace firtp
