#include <firtp/mode_tuning.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace firtp {
namespace {

constexpr double same_frequency = 1e-9;   // relative: one mode listed on several axes
constexpr double ceil_slack = 1e-9;       // k = ceil(L f - slack): a bound already on a zero keeps its k
constexpr double band_step = 5e-4;        // scan of the frequency error; edges then bisected
constexpr double band_floor = -0.9;       // lowest frequency error searched
constexpr double spread_low = 0.01, spread_high = 0.45, spread_step = 0.005;
constexpr double max_mode_periods = 1e6;  // k at most: what the INI reader allows for [FIRTP]MODES

void check_mode(const StructuralMode& m) {
    if (!(std::isfinite(m.frequency_hz) && m.frequency_hz > 0.0))
        throw std::invalid_argument("mode frequencies must be positive and finite");
    if (!(std::isfinite(m.damping) && m.damping >= 0.0 && m.damping < 1.0))
        throw std::invalid_argument("mode damping must lie in [0, 1)");
}

void check_spread(double spread) {
    if (!(std::isfinite(spread) && spread >= 0.0 && spread < 0.5))
        throw std::invalid_argument("the straddle spread must lie in (0, 0.5)");
}

std::string short_number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// A stage to place: its zero frequency and the mode it serves (-1: a stage for the limits only).
struct Slot {
    double zero_hz = 0.0;
    int mode = -1;
};

std::vector<Slot> tuned_slots(const std::vector<StructuralMode>& modes, const ModeTuning& tuning,
                              std::vector<double>& spreads) {
    std::vector<Slot> slots;
    spreads.assign(modes.size(), 0.0);
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const double f = modes[m].frequency_hz;
        const int index = static_cast<int>(m);
        switch (tuning.robust) {
        case RobustTuning::none:
            slots.push_back({f, index});
            break;
        case RobustTuning::double_stage:
            slots.push_back({f, index});
            slots.push_back({f, index});
            break;
        case RobustTuning::straddle: {
            const double d = tuning.spread > 0.0 ? tuning.spread : straddle_spread(modes[m].damping);
            spreads[m] = d;
            if (!std::isfinite(f * (1.0 + d)))
                throw std::invalid_argument(short_number(f) + " Hz: the straddled zero f (1 + spread) is not finite");
            slots.push_back({f * (1.0 - d), index});
            slots.push_back({f * (1.0 + d), index});
            break;
        }
        }
    }
    return slots;
}

// The smallest T = k / zero (k >= 1) not below `bound`; NaN when k > max_mode_periods (also for an
// infinite product) or T is not positive and finite: k is converted to int only after this check.
double raised(double bound, double zero_hz, int* k_out = nullptr) {
    const double k = std::max(1.0, std::ceil(bound * zero_hz - ceil_slack));
    const double t = k / zero_hz;
    if (!(k <= max_mode_periods && std::isfinite(t) && t > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (k_out) *k_out = static_cast<int>(k);
    return t;
}

// Why no stage tuned to `zero_hz` reaches `bound` (raised() gave NaN).
std::string unraisable(double bound, double zero_hz) {
    if (!std::isfinite(1.0 / zero_hz))
        return short_number(zero_hz) + " Hz: one period of this mode (1 / f) is not a finite time";
    return short_number(zero_hz) + " Hz: a filter stage of at least " + short_number(bound) +
           " s would span more than a million periods of this mode";
}

}  // namespace

int tuned_stage_count(const ModeTuning& tuning) {
    const int per_mode = tuning.robust == RobustTuning::none ? 1 : 2;
    return per_mode * static_cast<int>(distinct_modes(tuning.modes).size());
}

std::vector<StructuralMode> distinct_modes(std::span<const StructuralMode> modes) {
    std::vector<StructuralMode> out;
    for (const StructuralMode& m : modes) {
        check_mode(m);
        const auto same = std::find_if(out.begin(), out.end(), [&](const StructuralMode& o) {
            return std::abs(o.frequency_hz - m.frequency_hz) <= same_frequency * m.frequency_hz;
        });
        if (same == out.end()) {
            out.push_back(m);
        } else {
            same->damping = std::min(same->damping, m.damping);
            if (same->axis != m.axis) same->axis = -1;
        }
    }
    return out;
}

TunedFilters tune_filters(std::span<const double> lower_bounds, int stages, const ModeTuning& tuning) {
    if (stages < 1 || stages > max_stages) throw std::invalid_argument("the chain needs 1 to 4 stages");
    check_spread(tuning.spread);
    TunedFilters result;
    result.modes = distinct_modes(tuning.modes);
    const std::vector<Slot> slots = tuned_slots(result.modes, tuning, result.spreads);
    const int n = std::max(stages, static_cast<int>(slots.size()));
    if (n > max_stages)
        throw std::invalid_argument(std::to_string(result.modes.size()) + " modes need " +
                                    std::to_string(slots.size()) + " stages" +
                                    (tuning.robust == RobustTuning::none ? "" : " (two a mode when robust)") +
                                    "; the chain has at most 4");

    // Lower bounds per rank, largest first (T1 >= v/a, T2 >= a/j, or given times).
    std::array<double, max_stages> bounds{};
    for (std::size_t i = 0; i < lower_bounds.size() && i < static_cast<std::size_t>(n); ++i) {
        if (!std::isfinite(lower_bounds[i])) throw std::invalid_argument("filter times must be finite");
        bounds[i] = std::max(lower_bounds[i], 0.0);  // <= 0: no bound
    }
    std::sort(bounds.begin(), bounds.end(), std::greater<>());  // unused ranks are 0: last

    // Items 0 .. slots-1 are tuned stages, the rest only keep the limits. Every assignment of items
    // to bounds (at most 4! = 24); for one assignment each item's smallest time is independent.
    std::array<int, max_stages> order{};
    std::iota(order.begin(), order.begin() + n, 0);
    double best = std::numeric_limits<double>::infinity();
    std::array<int, max_stages> best_order{};
    std::string too_long;  // the first stage that no k reaches, or a delay that is not finite
    do {
        double td = 0.0;
        bool feasible = true;
        for (int item = 0; item < n && feasible; ++item) {
            const double bound = bounds[order[item]];
            if (item < static_cast<int>(slots.size())) {
                const double zero = slots[item].zero_hz;
                const double t = raised(bound, zero);
                feasible = !std::isnan(t);
                if (!feasible && too_long.empty()) too_long = unraisable(bound, zero);
                td += feasible ? t : 0.0;
            } else if (bound > 0.0) {
                td += bound;
            } else {
                feasible = false;
            }
        }
        if (feasible && !std::isfinite(td)) {
            feasible = false;
            if (too_long.empty()) too_long = "the filter delay T1 + ... + Tn is not finite";
        }
        if (feasible && td < best * (1.0 - 1e-12)) {
            best = td;
            best_order = order;
        }
    } while (std::next_permutation(order.begin(), order.begin() + n));

    if (!std::isfinite(best)) {
        // Too few bounds for the stages without a mode: name the first time that is missing.
        const auto positive = std::count_if(bounds.begin(), bounds.begin() + n, [](double b) { return b > 0.0; });
        if (positive + static_cast<long>(slots.size()) >= n && !too_long.empty()) throw std::invalid_argument(too_long);
        throw std::invalid_argument("T" + std::to_string(positive + static_cast<long>(slots.size()) + 1) +
                                    " is neither given nor derivable from the axis limits or a mode");
    }

    std::array<TunedStage, max_stages> chosen{};
    for (int item = 0; item < n; ++item) {
        const double bound = bounds[best_order[item]];
        TunedStage& s = chosen[item];
        if (item < static_cast<int>(slots.size())) {
            const Slot& slot = slots[item];
            s.time = raised(bound, slot.zero_hz, &s.k);
            s.mode = slot.mode;
            s.zero_hz = slot.zero_hz;
        } else {
            s.time = bound;
        }
    }
    std::stable_sort(chosen.begin(), chosen.end(),  // unused ranks have time 0: last
                    
                     [](const TunedStage& a, const TunedStage& b) { return a.time > b.time; });
    result.stages = chosen;
    result.filters.stages = n;
    for (int i = 0; i < n; ++i) result.filters.T[i] = chosen[i].time;
    return result;
}

TunedFilters tune_filter_times(const MachineLimits& limits, int stages, std::span<const double> given,
                               const ModeTuning& tuning) {
    const std::array<double, max_stages> bounds = limit_filter_times(limits, given);
    return tune_filters(bounds, stages, tuning);
}

double chain_magnitude(const FilterTimes& filters, double frequency_hz) {
    double m = 1.0;
    for (int i = 0; i < filters.stages; ++i) {
        const double x = std::numbers::pi * frequency_hz * filters.T[i];
        m *= x == 0.0 ? 1.0 : std::abs(std::sin(x) / x);
    }
    return m;
}

double stage_residual_vibration(double T, double frequency_hz, double damping) {
    // V = |1 - exp(-p T)| / (w T), p = w (zeta + j sqrt(1 - zeta^2)), written without cancellation.
    const double w = 2.0 * std::numbers::pi * frequency_hz;
    const double sigma_t = damping * w * T;
    const double theta = w * std::sqrt(1.0 - damping * damping) * T;
    const double decay = std::exp(-sigma_t);
    const double half = std::sin(0.5 * theta);
    const double re = -std::expm1(-sigma_t) + decay * 2.0 * half * half;  // 1 - e^-sT cos(theta)
    const double im = decay * std::sin(theta);
    return std::hypot(re, im) / (w * T);
}

double residual_vibration(const FilterTimes& filters, double frequency_hz, double damping) {
    double v = 1.0;
    for (int i = 0; i < filters.stages; ++i)
        v *= stage_residual_vibration(filters.T[i], frequency_hz, damping);
    return v;
}

FrequencyBand vibration_band(const FilterTimes& tuned, const FilterTimes* reference, double frequency_hz,
                             double damping, double threshold, double max_error) {
    const auto within = [&](double e) {
        const double f = frequency_hz * (1.0 + e);
        const double v = residual_vibration(tuned, f, damping);
        const double ref = reference ? residual_vibration(*reference, f, damping) : 1.0;
        return v <= threshold * ref;
    };
    FrequencyBand band;
    if (!within(0.0)) return band;
    band.empty = false;
    // Walks from 0 towards `limit` while within; bisects the step where it leaves.
    const auto edge = [&](double limit, bool& open) {
        const double direction = limit > 0.0 ? 1.0 : -1.0;
        double inside = 0.0;
        for (;;) {
            const double next = inside + direction * band_step;
            if (direction * (next - limit) >= 0.0) {
                open = within(limit);
                if (open) return limit;
                double lo = inside, hi = limit;
                for (int i = 0; i < 50; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    (within(mid) ? lo : hi) = mid;
                }
                return lo;
            }
            if (!within(next)) {
                double lo = inside, hi = next;
                for (int i = 0; i < 50; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    (within(mid) ? lo : hi) = mid;
                }
                return lo;
            }
            inside = next;
        }
    };
    bool open_below = false;
    band.low = edge(band_floor, open_below);
    band.high = edge(max_error, band.open_above);
    return band;
}

FilterTimes mode_stages(const StructuralMode& mode, RobustTuning robust, double spread) {
    check_mode(mode);
    check_spread(spread);
    FilterTimes f;
    const double period = 1.0 / mode.frequency_hz;
    switch (robust) {
    case RobustTuning::none:
        f.stages = 1;
        f.T[0] = period;
        break;
    case RobustTuning::double_stage:
        f.stages = 2;
        f.T[0] = f.T[1] = period;
        break;
    case RobustTuning::straddle: {
        const double d = spread > 0.0 ? spread : straddle_spread(mode.damping);
        f.stages = 2;
        f.T[0] = period / (1.0 - d);
        f.T[1] = period / (1.0 + d);
        break;
    }
    }
    return f;
}

double straddle_spread(double damping, double threshold) {
    // V depends on f T and zeta only: search at f = 1 Hz.
    StructuralMode unit{1.0, damping, -1};
    check_mode(unit);
    double best_spread = spread_low, best_width = -1.0;
    for (double d = spread_low; d <= spread_high + 1e-12; d += spread_step) {
        const FilterTimes pair = mode_stages(unit, RobustTuning::straddle, d);
        const FrequencyBand band = vibration_band(pair, nullptr, 1.0, damping, threshold);
        if (band.empty) continue;
        const double width = band.high - band.low;
        if (width > best_width + 1e-9) best_width = width, best_spread = d;
    }
    return best_spread;
}

}  // namespace firtp
