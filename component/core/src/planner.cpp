#include <firtp/planner.hpp>

#include <firtp/overlap.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace firtp {

namespace {

constexpr double collinear_angle = 1e-9;  // rad: joined into one pulse below this turn
constexpr double max_pulse_periods = 1e16;  // longest pulse Tv = L / F, in servo periods (int64 ticks reach 9.2e18)

double longest_pulse(double period) { return max_pulse_periods * period; }  // s

bool finite(const AxisVector& v) { return v.allFinite(); }

// t = tick * period + offset, offset normalised into [0, period).
void normalise(std::int64_t& tick, double& offset, double period) {
    const double whole = std::floor(offset / period);
    tick += static_cast<std::int64_t>(whole);
    offset -= whole * period;
    if (offset >= period) offset -= period, ++tick;
    if (offset < 0.0) offset = 0.0;
}

constexpr double min_feed_fraction = 0.02;  // lower feeds are tried only when this one fails too
constexpr int max_quarters = 20;            // below it by quarters: 0.02 / 4^20 = 2e-14 at the least
constexpr double crawl_fraction = 1e-3;     // Stats::crawling: below 0.1 % of the programmed feed

// The highest feed (a fraction of `feed`, bisected in `steps`) that `ok` accepts; below
// min_feed_fraction by quarters, never below `slowest` (the pulse must fit the servo clock).
// None when even that fails: a stop slow enough always holds (the stop scenario of the committed
// samples was checked), so none means those samples break the check, whatever the feed.
template <class Feasible>
std::optional<double> highest_feasible_feed(Feasible&& ok, double feed, int steps, double slowest) {
    if (ok(feed)) return feed;
    double lo = min_feed_fraction, hi = 1.0;
    for (int quarters = 0; !ok(feed * lo); ++quarters, hi = lo, lo *= 0.25)
        if (quarters == max_quarters || feed * lo * 0.25 < slowest) return std::nullopt;
    for (int i = 0; i < steps; ++i) (ok(feed * 0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
    return feed * lo;
}

// Seconds from (tick_a, offset_a) to (tick_b, offset_b).
double seconds_between(std::int64_t tick_a, double offset_a, std::int64_t tick_b, double offset_b, double period) {
    return static_cast<double>(tick_b - tick_a) * period + (offset_b - offset_a);
}

}  // namespace

Planner::Planner(const PlannerParameters& parameters, const FirChain& chain, const AxisVector& start)
    : parameters_(parameters), chain_(&chain), window_(chain, parameters) {
    last_.end = start;
    window_.reset(start, 0);
}

void Planner::reset(const AxisVector& position, std::int64_t tick) {
    last_ = Last{};
    last_.end = position;
    window_.reset(position, tick);
}

Planner::Start Planner::schedule(double tk, std::int64_t now) const {
    // The next pulse starts Td - Tk after the previous one ended (Eq. 11), never in the past.
    const double period = parameters_.period;
    Start s{last_.end_tick, last_.end_offset + (chain_->delay() - tk), tk};
    normalise(s.tick, s.offset, period);
    if (tk == 0.0 && s.offset > 0.0) {
        // A stop: rest until the next servo sample so that one sample lands exactly on the
        // corner; otherwise the straight line between samples would cut it.
        ++s.tick;
        s.offset = 0.0;
    }
    if (s.tick < now) s = {now, 0.0, latest_overlap(now)};  // too late for the overlap asked for
    return s;
}

double Planner::latest_overlap(std::int64_t now) const {
    const double td = chain_->delay();
    return std::clamp(td - seconds_between(last_.end_tick, last_.end_offset, now, 0.0, parameters_.period), 0.0, td);
}

// Several blocks may share a filter window (or limits must hold): try schedules on the samples.
// Full overlap at full feed first; on shallow turns a lower feed before a shorter overlap (a
// chorded curve keeps moving); else the largest overlap that holds. Tk = 0 at a low enough feed
// always holds.
std::optional<Planner::Choice> Planner::search_window(const AxisVector& delta, double length, double feed,
                                                      double beta, double epsilon, std::int64_t now) const {
    const double tk_high = latest_overlap(now);
    const double slowest = length / longest_pulse(parameters_.period);
    auto candidate = [&](double tk, double f) {
        const Start s = schedule(tk, now);
        return Candidate{delta, length / f, s.tick, s.offset};
    };
    constexpr int search_stride = 12;  // the quick search looks at every 12th sample
    auto ok = [&](double tk, double f) { return window_.feasible(candidate(tk, f), search_stride); };
    auto exact = [&](double tk, double f) { return window_.feasible(candidate(tk, f)); };
    // The quick search may miss a limit between its samples: confirm the choice on every sample,
    // else bisect the overlap with full checks below it, else lower the feed of a stop.
    auto confirmed = [&](Choice choice) -> std::optional<Choice> {
        if (exact(choice.tk, choice.feed)) return choice;
        if (choice.tk > 0.0 && exact(0.0, choice.feed)) {
            double lo = 0.0, hi = choice.tk;
            for (int i = 0; i < 8; ++i) (exact(0.5 * (lo + hi), choice.feed) ? lo : hi) = 0.5 * (lo + hi);
            return Choice{lo, choice.feed};
        }
        const auto stop = highest_feasible_feed([&](double f) { return exact(0.0, f); }, choice.feed, 10, slowest);
        if (!stop) return std::nullopt;
        return Choice{0.0, *stop};
    };
    constexpr double shallow = 0.5;  // rad (about 30 degrees)
    constexpr int steps = 14;
    constexpr int bracket_steps = 8;  // below the estimate the bracket is estimate / 16 wide: / 256 more
    // The two-block answer (Eq. 13/14 or the any-chain form) is close: the sampled one is a little
    // smaller. Full overlap is worth a try only where it does not rule it out.
    const double estimate = std::clamp(overlap_symmetric(*chain_, epsilon, feed, beta), 0.0, tk_high);
    if ((estimate >= tk_high || beta < shallow) && ok(tk_high, feed)) return confirmed({tk_high, feed});
    if (beta < shallow && ok(tk_high, feed * min_feed_fraction)) {
        const auto full = highest_feasible_feed([&](double f) { return ok(tk_high, f); }, feed, steps, slowest);
        return confirmed({tk_high, full.value_or(feed * min_feed_fraction)});
    }
    // Bracket below the estimate, then bisect.
    double lo = 0.0, hi = tk_high;
    if (estimate > 0.0) {
        if (estimate < tk_high && ok(estimate, feed)) lo = estimate;
        else if (hi = std::min(hi, estimate), ok(estimate * (15.0 / 16.0), feed)) lo = estimate * (15.0 / 16.0);
    }
    if (lo > 0.0 || ok(0.0, feed)) {
        for (int i = 0; i < bracket_steps; ++i) (ok(0.5 * (lo + hi), feed) ? lo : hi) = 0.5 * (lo + hi);
        return confirmed({lo, feed});
    }
    // Even a stop breaks a limit: the block itself is too fast for the filters (short T). No feed
    // by the quick search: the full check searches from the block's feed.
    const auto stop = highest_feasible_feed([&](double f) { return ok(0.0, f); }, feed, steps, slowest);
    return confirmed({0.0, stop.value_or(feed)});
}

std::optional<double> Planner::feed_for_start(const AxisVector& delta, double length, double feed,
                                              const Start& start) const {
    return highest_feasible_feed([&](double f) { return window_.feasible({delta, length / f, start.tick, start.offset}); },
                                 feed, 14, length / longest_pulse(parameters_.period));
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
    // The pulse must fit the servo clock (int64 ticks): a feed of 1e-300, or a length that
    // overflows, gives Tv = inf, which would be converted to a tick count (undefined behaviour).
    if (!(length / block.feed <= longest_pulse(parameters_.period))) return Result::invalid_block;
    if (out.free() == 0) return Result::queue_full;

    const double period = parameters_.period;
    const double td = chain_->delay();
    const std::int64_t now = out.now_tick();
    double feed = block.feed;
    double tv = length / feed;  // Eq. 5

    CornerReport report;
    bool joined = false;
    Start start{now, 0.0, 0.0};  // from rest: at once
    auto refuse = [&] {  // nothing committed: the tool rests at the previous block's end, as checked
        ++stats_.refused;
        return Result::invalid_block;
    };
    if (!last_.moving && window_.checks_limits()) {
        // Even alone a pulse can break a limit: shorter than T1 - T2, it doubles the jerk F / (T1 T2).
        const std::optional<double> f = feed_for_start(delta, length, feed, start);
        if (!f) return refuse();
        feed = *f;
        tv = length / feed;
    }
    if (last_.moving) {
        const double beta = turn_angle(last_.run_delta, delta);
        report.line = last_.line;
        report.point = last_.end;
        report.beta = beta;
        report.epsilon = last_.tolerance;
        report.exact_stop = last_.termination == Termination::exact_stop;
        window_.set_corner_tolerance(last_.tolerance, !report.exact_stop);
        const bool in_window = parameters_.fixed_overlap < 0.0 &&
                               (last_.run_tv < td || tv < td || window_.checks_limits());
        double tk = 0.0;
        if (report.exact_stop) {
            tk = 0.0;
            if (window_.checks_limits()) {  // after a stop only the feed can keep the limits
                const std::optional<double> f = feed_for_start(delta, length, feed, schedule(0.0, now));
                if (!f) return refuse();
                feed = *f;
                tv = length / feed;
            }
        } else if (in_window) {
            const std::optional<Choice> choice = search_window(delta, length, feed, beta, last_.tolerance, now);
            if (!choice) return refuse();
            tk = choice->tk;
            feed = choice->feed;
            tv = length / feed;
            report.tk_tolerance = tk;
        } else {
            // Equal feed, straight on, and the previous corner's overlap inside the last block: one pulse.
            joined = beta < collinear_angle && std::abs(block.feed - last_.feed) <= 1e-12 * last_.feed &&
                     last_.run_tv >= last_.tk_in + period;
            // Clamp (paper notes): this corner gets what the previous one left of the incoming
            // pulse, and at most half of the outgoing one, so no window holds three blocks. One
            // servo period more stays free: the sampled error bound looks that far past a window.
            const double tk_max = joined ? td : std::clamp(
                std::min({td, last_.run_tv + td - last_.tk_in - period, 0.5 * (tv + td - period)}), 0.0, td);
            const CornerModel model{chain_, last_.run_delta, last_.run_tv, delta, tv};
            if (joined) {
                tk = td;
            } else if (parameters_.fixed_overlap >= 0.0) {
                tk = std::min(parameters_.fixed_overlap, tk_max);
                report.tk_tolerance = parameters_.fixed_overlap;
            } else {
                tk = solve_overlap(model, last_.tolerance, parameters_.tolerance_meaning, period, tk_max);
                report.tk_tolerance = tk;
                if (corner && tk == tk_max && tk_max < td)  // report-only: what the clamp took away
                    report.tk_tolerance = solve_overlap(model, last_.tolerance, parameters_.tolerance_meaning, period, td);
            }
        }
        start = schedule(tk, now);
        joined = joined && start.tk == td;
        report.tk = start.tk;
        if (corner && !joined && !report.exact_stop) {  // report-only
            const CornerModel model{chain_, last_.run_delta, last_.run_tv, delta, tv};
            report.predicted_error = parameters_.tolerance_meaning == ToleranceMeaning::contour
                                         ? model.contour_error(start.tk)
                                         : model.corner_error(start.tk);
        }
    }

    PlannedBlock planned;
    planned.delta = delta;
    planned.end = block.target;
    planned.tv = tv;
    planned.line = block.line;
    planned.type = block.type;
    planned.start_tick = start.tick;
    planned.start_offset = start.offset;
    if (!out.push(planned)) return Result::queue_full;
    window_.commit({delta, tv, start.tick, start.offset});
    if (feed < block.feed) ++stats_.slowed;
    if (feed < block.feed * crawl_fraction) ++stats_.crawling;

    Last next = last_;
    next.end = block.target;
    next.feed = feed;
    next.termination = block.termination;
    next.tolerance = block.tolerance;
    next.line = block.line;
    next.moving = true;
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
        next.tk_in = start.tk;
    }
    const bool formed_corner = last_.moving;
    last_ = next;
    if (formed_corner && corner) *corner = report;
    if (formed_corner && has_corner) *has_corner = true;
    return Result::ok;
}

}  // namespace firtp
