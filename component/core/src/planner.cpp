#include <firtp/planner.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

namespace {

constexpr double collinear_angle = 1e-9;  // rad: joined into one pulse below this turn

bool finite(const AxisVector& v) { return v.allFinite(); }

// t = tick * period + offset, offset normalised into [0, period).
void normalise(std::int64_t& tick, double& offset, double period) {
    const double whole = std::floor(offset / period);
    tick += static_cast<std::int64_t>(whole);
    offset -= whole * period;
    if (offset >= period) offset -= period, ++tick;
    if (offset < 0.0) offset = 0.0;
}

// Seconds from (tick_a, offset_a) to (tick_b, offset_b).
double seconds_between(std::int64_t tick_a, double offset_a, std::int64_t tick_b, double offset_b, double period) {
    return static_cast<double>(tick_b - tick_a) * period + (offset_b - offset_a);
}

}  // namespace

Planner::Planner(const PlannerParameters& parameters, const FirChain& chain, const AxisVector& start)
    : parameters_(parameters), chain_(&chain) {
    last_.end = start;
}

void Planner::reset(const AxisVector& position) {
    last_ = Last{};
    last_.end = position;
}

Result Planner::add(const Block& block, Interpolator& out, CornerReport* corner, bool* has_corner) {
    if (has_corner) *has_corner = false;
    const bool blend = block.termination == Termination::blend;
    if (!finite(block.target) || !std::isfinite(block.feed) || block.feed <= 0.0 ||
        std::isnan(block.tolerance) || (blend && !(block.tolerance > 0.0)))
        return Result::invalid_block;

    const AxisVector delta = block.target - last_.end;
    const double length = delta.norm();
    if (length < min_block_length) return Result::ok;
    if (out.free() == 0) return Result::queue_full;

    const double period = parameters_.period;
    const double td = chain_->delay();
    const double tv = length / block.feed;  // Eq. 5
    const std::int64_t now = out.now_tick();

    PlannedBlock planned;
    planned.delta = delta;
    planned.end = block.target;
    planned.tv = tv;
    planned.line = block.line;
    planned.type = block.type;

    Last next = last_;
    next.end = block.target;
    next.feed = block.feed;
    next.termination = block.termination;
    next.tolerance = block.tolerance;
    next.line = block.line;
    next.moving = true;

    CornerReport report;
    bool joined = false;
    double tk = 0.0;
    if (!last_.moving) {
        planned.start_tick = now;  // from rest: start at once
        planned.start_offset = 0.0;
    } else {
        const double beta = turn_angle(last_.run_delta, delta);
        report.line = last_.line;
        report.point = last_.end;
        report.beta = beta;
        report.epsilon = last_.tolerance;
        report.exact_stop = last_.termination == Termination::exact_stop;
        // Equal feed, straight on, and the previous corner's overlap inside the last block: one pulse.
        joined = !report.exact_stop && beta < collinear_angle &&
                 std::abs(block.feed - last_.feed) <= 1e-12 * last_.feed && last_.run_tv >= last_.tk_in + period;
        if (joined) {
            tk = td;
        } else if (!report.exact_stop) {
            // Clamp (paper notes): this corner gets what the previous one left of the incoming
            // pulse, and at most half of the outgoing one, so no window holds three blocks. One
            // servo period more stays free: the sampled error bound looks that far past a window.
            const double tk_max = std::clamp(
                std::min({td, last_.run_tv + td - last_.tk_in - period, 0.5 * (tv + td - period)}), 0.0, td);
            const CornerModel model{chain_, last_.run_delta, last_.run_tv, delta, tv};
            if (parameters_.fixed_overlap >= 0.0) {
                tk = std::min(parameters_.fixed_overlap, tk_max);
                report.tk_tolerance = parameters_.fixed_overlap;
            } else {
                tk = solve_overlap(model, last_.tolerance, parameters_.tolerance_meaning, period, tk_max);
                report.tk_tolerance = tk;
                if (corner && tk == tk_max && tk_max < td)  // report-only: what the clamp took away
                    report.tk_tolerance = solve_overlap(model, last_.tolerance, parameters_.tolerance_meaning, period, td);
            }
        }
        // The next pulse starts Td - Tk after the previous one ended (Eq. 11), never in the past.
        planned.start_tick = last_.end_tick;
        planned.start_offset = last_.end_offset + (td - tk);
        normalise(planned.start_tick, planned.start_offset, period);
        if (tk == 0.0 && planned.start_offset > 0.0) {
            // A stop: rest until the next servo sample so that one sample lands exactly on the
            // corner; otherwise the straight line between samples would cut it.
            ++planned.start_tick;
            planned.start_offset = 0.0;
        }
        if (planned.start_tick < now) {
            planned.start_tick = now;
            planned.start_offset = 0.0;
            tk = std::max(0.0, td - seconds_between(last_.end_tick, last_.end_offset, now, 0.0, period));
            joined = joined && tk == td;
        }
        report.tk = tk;
        if (corner && !joined) {  // report-only
            const CornerModel model{chain_, last_.run_delta, last_.run_tv, delta, tv};
            report.predicted_error = parameters_.tolerance_meaning == ToleranceMeaning::contour
                                         ? model.contour_error(tk)
                                         : model.corner_error(tk);
        }
    }

    if (!out.push(planned)) return Result::queue_full;

    next.end_tick = planned.start_tick;
    next.end_offset = planned.start_offset + tv;
    normalise(next.end_tick, next.end_offset, period);
    if (joined) {
        next.run_delta = last_.run_delta + delta;
        next.run_tv = last_.run_tv + tv;
        next.tk_in = last_.tk_in;
    } else {
        next.run_delta = delta;
        next.run_tv = tv;
        next.tk_in = tk;
    }
    const bool formed_corner = last_.moving;
    last_ = next;
    if (formed_corner && corner) *corner = report;
    if (formed_corner && has_corner) *has_corner = true;
    return Result::ok;
}

}  // namespace firtp
