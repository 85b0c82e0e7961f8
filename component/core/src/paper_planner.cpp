#include <firtp/paper_planner.hpp>

#include <firtp/junction.hpp>
#include <firtp/overlap.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

namespace {

constexpr double collinear_angle = 1e-9;    // rad: joined into one pulse below this turn
constexpr double max_pulse_periods = 1e16;  // longest pulse Tv = L / F, in servo periods (int64 ticks reach 9.2e18)
constexpr double min_feed_fraction = 0.02;  // lower feeds are tried only when this one fails too
constexpr int max_quarters = 20;            // below it by quarters: 0.02 / 4^20 = 2e-14 at the least
constexpr double crawl_fraction = 1e-3;     // stats: below 0.1 % of the programmed feed
constexpr double shallow = 0.5;             // rad (about 30 degrees): a lower feed before a shorter overlap
constexpr int clock_phases = 8;             // sample grids checked at each corner
constexpr double error_margin = 1e-5;       // of epsilon, for the approach found by Newton's method

double longest_pulse(double period) { return max_pulse_periods * period; }

double seconds_between(std::int64_t tick_a, double offset_a, std::int64_t tick_b, double offset_b, double period) {
    return static_cast<double>(tick_b - tick_a) * period + (offset_b - offset_a);
}

// The highest feed (a fraction of `feed`, bisected in `steps`) that `ok` accepts; below
// min_feed_fraction by quarters, never below `slowest`. None when even that fails.
template <class Feasible>
std::optional<double> highest_feasible_feed(Feasible&& ok, double feed, int steps, double slowest) {
    if (ok(feed)) return feed;
    double lo = min_feed_fraction, hi = 1.0;
    for (int quarters = 0; !ok(feed * lo); ++quarters, hi = lo, lo *= 0.25)
        if (quarters == max_quarters || feed * lo * 0.25 < slowest) return std::nullopt;
    for (int i = 0; i < steps; ++i) (ok(feed * 0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
    return feed * lo;
}

}  // namespace

PaperPlanner::PaperPlanner(const PlannerParameters& parameters, const FirChain& chain, Timeline& timeline,
                           const AxisVector& start)
    : parameters_(parameters), limits_(planned_limits(parameters)), chain_(&chain), timeline_(&timeline),
      sweep_(std::max<std::size_t>(parameters.queue_capacity, 2) + 8) {
    for (int a = 0; a < limits_.axes; ++a) {
        const AxisLimits& l = limits_.axis[a];
        check_limits_ = check_limits_ || l.max_velocity > 0.0 || l.max_acceleration > 0.0 || l.max_jerk > 0.0;
    }
    legs_.reserve(std::max<std::size_t>(parameters.queue_capacity, 2) + 8);
    last_.end = start;
    timeline_->widen(chain.delay());
}

void PaperPlanner::reset(const AxisVector& position) {
    last_ = Last{};
    last_.end = position;
    corner_count_ = 0;
    pending_dwell_ = 0.0;
}

bool PaperPlanner::take_report(CornerReport& report) {
    if (report_count_ == 0) return false;
    report = reports_[report_head_];
    report_head_ = (report_head_ + 1) % reports_.size();
    --report_count_;
    return true;
}

PaperPlanner::Start PaperPlanner::schedule(double Tk, std::int64_t now, bool rest, double dwell) const {
    // The next pulse starts Td - Tk after the previous one ended (Eq. 11), never in the past.
    const double period = parameters_.period;
    Start s{last_.end_tick, last_.end_offset + (chain_->delay() - Tk), Tk};
    s.offset += dwell;  // a stop's rest starts on the first sample after it, as without a dwell
    normalise(s.tick, s.offset, period);
    if (Tk == 0.0 && (rest || s.offset > 0.0)) {
        // A stop: rest until the next servo sample so that one sample lands exactly on the
        // corner; otherwise the straight line between samples would cut it. A blended corner
        // that needs a stop rests at least one period (until a sample after it): then a sample
        // lands on it whatever the phase of the clock (a scaled clock samples off the grid).
        s.tick += rest && s.offset > 0.0 ? 2 : 1;
        s.offset = 0.0;
    }
    if (s.tick < now) s = {now, 0.0, latest_overlap(now)};  // too late for the overlap asked for
    return s;
}

double PaperPlanner::latest_overlap(std::int64_t now) const {
    const double td = chain_->delay();
    return std::clamp(td - seconds_between(last_.end_tick, last_.end_offset, now, 0.0, parameters_.period), 0.0, td);
}

Leg PaperPlanner::candidate(const AxisVector& delta, double length, double feed, const Start& start,
                            const Block& block) const {
    Leg leg;
    leg.delta = delta;
    leg.end = block.target;
    leg.tv = length / feed;
    leg.rise_tick = start.tick;
    leg.rise_offset = start.offset;
    leg.fall = leg.tv;
    leg.rising.chain = chain_;
    leg.falling.chain = chain_;
    leg.line = block.line;
    leg.type = block.type;
    leg.last_of_block = true;
    return leg;
}

void PaperPlanner::to_timed(const Leg& leg, TimedLeg& out) const {
    out.delta = leg.delta;
    out.tv = leg.tv;
    out.rise = -timeline_->local_time(leg, timeline_->now());
    out.fall = leg.fall;
    out.rising = leg.rising;
    out.falling = leg.falling;
}

search::Probe PaperPlanner::feasible(const Leg& leg, double corner_epsilon, bool corner_bound) {
    const double td = chain_->delay();
    // The legs that can overlap the candidate, oldest first, and the candidate last.
    TimedLeg c;
    to_timed(leg, c);
    std::size_t first = timeline_->size();
    while (first > 0) {
        const Leg& l = timeline_->at(first - 1);
        if (-timeline_->local_time(l, timeline_->now()) + l.finish() < c.rise - td && first < timeline_->size()) break;
        --first;
    }
    legs_.clear();
    for (std::size_t k = first; k < timeline_->size(); ++k) {
        TimedLeg t;
        to_timed(timeline_->at(k), t);
        legs_.push_back(t);
    }
    legs_.push_back(c);
    index_legs(legs_);
    const std::uint64_t first_leg = pushed_ - (timeline_->size() - first);  // count of legs_[0]
    if (check_limits_) {
        const LimitCheck l = sweep_.check(legs_, std::max(c.rise, 0.0), c.finish(), limits_, parameters_.period);
        if (!l.ok) return {false, -1.0};
    }
    // What bounds the motion near `guess` (closest_approach's sag): Newton moves at most 24
    // periods, a chord spans one more.
    auto bounds_near = [&](double guess, double limit) {
        const double period = parameters_.period;
        ApproachBounds b = chain_bounds(legs_, *chain_, guess - 25.0 * period, guess + 25.0 * period);
        b.enough = b.too_far = limit;
        return b;
    };
    double margin = 1.0;
    auto approach_ok = [&](std::size_t leg_index, double guess, double epsilon) {
        const double limit = epsilon * (1.0 - error_margin);
        // The contour: the samples across the window. The corner: the clock is scaled by the
        // override and leaves the sample grid, so every phase of it.
        const double error = parameters_.tolerance_meaning == ToleranceMeaning::contour
                                 ? contour_error(legs_, leg_index, guess, td, parameters_.period)
                                 : closest_approach(legs_, leg_index, guess, parameters_.period, clock_phases,
                                                    bounds_near(guess, limit))
                                       .distance;
        if (limit > 0.0) margin = std::min(margin, (limit - error) / limit);
        return error <= limit;
    };
    // The corner this candidate forms, and earlier ones its rising kernel still reaches.
    if (corner_bound && legs_.size() >= 2 && std::isfinite(corner_epsilon)) {
        const double guess = 0.5 * (c.rise + (legs_[legs_.size() - 2].rise + legs_[legs_.size() - 2].fall + td));
        if (!approach_ok(legs_.size() - 2, guess, corner_epsilon)) return {false, margin};
    }
    const double now = static_cast<double>(timeline_->now()) * parameters_.period;
    for (std::size_t k = 0; k < corner_count_; ++k) {
        const Corner& corner = corners_[k];
        if (corner.window_end - now <= c.rise || corner.leg < first_leg) continue;
        if (!approach_ok(static_cast<std::size_t>(corner.leg - first_leg), corner.guess - now, corner.epsilon))
            return {false, margin};
    }
    return {true, margin};
}

std::optional<double> PaperPlanner::feed_for_start(const AxisVector& delta, double length, double feed,
                                                   const Start& start, const Block& block) {
    return highest_feasible_feed(
        [&](double f) { return feasible(candidate(delta, length, f, start, block), 0.0, false).ok; },
        feed, 14, length / longest_pulse(parameters_.period));
}

// Several blocks may share a filter window (or limits must hold): try schedules and check them.
// Full overlap at full feed first; on shallow turns a lower feed before a shorter overlap (a
// chorded curve keeps moving); else the largest overlap that holds. Tk = 0 at a low enough feed
// always holds.
std::optional<PaperPlanner::Choice> PaperPlanner::search(const AxisVector& delta, double length, double feed,
                                                          double beta, double epsilon, const Block& block) {
    const std::int64_t now = timeline_->now();
    const double Tk_high = latest_overlap(now);
    const double slowest = length / longest_pulse(parameters_.period);
    auto probe = [&](double Tk, double f) {
        return feasible(candidate(delta, length, f, schedule(Tk, now, Tk == 0.0), block), epsilon, true);
    };
    auto ok = [&](double Tk, double f) { return probe(Tk, f).ok; };
    constexpr int steps = 14;
    const double estimate = std::clamp(overlap_symmetric(*chain_, epsilon, feed, beta), 0.0, Tk_high);
    std::optional<search::Probe> hi_failed;  // hi's test at the feed, where it was made and failed
    if (estimate >= Tk_high || beta < shallow) {
        const search::Probe at_high = probe(Tk_high, feed);
        if (at_high.ok) return Choice{Tk_high, feed};
        hi_failed = at_high;
    }
    if (beta < shallow && ok(Tk_high, feed * min_feed_fraction)) {
        const auto full = highest_feasible_feed([&](double f) { return ok(Tk_high, f); }, feed, steps, slowest);
        return Choice{Tk_high, full.value_or(feed * min_feed_fraction)};
    }
    // Bracket below the estimate, then bisect.
    double lo = 0.0, hi = Tk_high;
    search::Probe at_lo;
    if (estimate > 0.0) {
        if (estimate < Tk_high && (at_lo = probe(estimate, feed)).ok) {
            lo = estimate;
        } else {
            if (estimate < Tk_high) hi = estimate, hi_failed = at_lo;
            if ((at_lo = probe(estimate * (15.0 / 16.0), feed)).ok) lo = estimate * (15.0 / 16.0);
        }
    }
    if (lo > 0.0 || (at_lo = probe(0.0, feed)).ok) {
        // 12 halvings (to Td / 4096 at most), guided by the corners' slack (search.hpp); from
        // both ends where hi failed (the estimate is close: the flip is found in a few tests).
        auto test = [&](double Tk) { return probe(Tk, feed); };
        lo = hi_failed && lo < hi ? search::halvings(test, lo, at_lo.margin, hi, hi_failed->margin, 12)
                                  : search::halvings(test, lo, at_lo.margin, hi, 12);
        return Choice{lo, feed};
    }
    // Even a stop breaks a limit: the block itself is too fast for the filters (short T).
    const auto stop = highest_feasible_feed([&](double f) { return ok(0.0, f); }, feed, steps, slowest);
    if (!stop) return std::nullopt;
    return Choice{0.0, *stop};
}

Result PaperPlanner::add(const Block& block) {
    const AxisVector delta = block.target - last_.end;
    const double length = delta.norm();
    if (length < min_block_length) {  // skipped; its dwell goes to the next block
        pending_dwell_ += block.dwell;
        return Result::skipped;
    }
    const double dwell = pending_dwell_ + block.dwell;
    // The pulse must fit the servo clock (int64 ticks): a feed of 1e-300, or a length that
    // overflows, gives Tv = inf, which would be converted to a tick count (undefined behaviour).
    if (!(length / block.feed <= longest_pulse(parameters_.period))) return Result::invalid_block;
    if (timeline_->free() == 0) return Result::queue_full;

    const double period = parameters_.period;
    const double td = chain_->delay();
    const std::int64_t now = timeline_->now();
    double feed = block.feed;
    double tv = length / feed;  // Eq. 5

    CornerReport report;
    bool joined = false;
    // From rest: at once, or after the dwell.
    Start start{now + static_cast<std::int64_t>(std::ceil(dwell / parameters_.period - 1e-9)), 0.0, 0.0};
    auto refuse = [&] {  // nothing committed: the tool rests at the previous block's end, as checked
        ++stats_.refused;
        return Result::infeasible;
    };
    if (!last_.moving && check_limits_) {
        // Even alone a pulse can break a limit: shorter than T1 - T2, it doubles the jerk F / (T1 T2).
        const std::optional<double> f = feed_for_start(delta, length, feed, start, block);
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
        report.exact_stop = last_.termination == Termination::exact_stop || dwell > 0.0;
        const bool in_window = parameters_.fixed_overlap < 0.0 && (last_.run_tv < td || tv < td || check_limits_);
        double Tk = 0.0;
        if (report.exact_stop) {
            if (check_limits_) {  // after a stop only the feed can keep the limits
                const std::optional<double> f = feed_for_start(delta, length, feed, schedule(0.0, now, false, dwell), block);
                if (!f) return refuse();
                feed = *f;
                tv = length / feed;
            }
        } else if (in_window) {
            const std::optional<Choice> choice = search(delta, length, feed, beta, last_.tolerance, block);
            if (!choice) return refuse();
            Tk = choice->Tk;
            feed = choice->feed;
            tv = length / feed;
            report.Tk_tolerance = Tk;
        } else {
            // Equal feed, straight on, and the previous corner's overlap inside the last block: one pulse.
            joined = beta < collinear_angle && std::abs(block.feed - last_.feed) <= 1e-12 * last_.feed &&
                     last_.run_tv >= last_.Tk_in + period;
            // Clamp (paper notes): this corner gets what the previous one left of the incoming
            // pulse, and at most half of the outgoing one, so no window holds three blocks. One
            // servo period more stays free: the sampled error bound looks that far past a window.
            const double Tk_max = joined ? td : std::clamp(
                std::min({td, last_.run_tv + td - last_.Tk_in - period, 0.5 * (tv + td - period)}), 0.0, td);
            const CornerModel model{chain_, last_.run_delta, last_.run_tv, delta, tv};
            if (joined) {
                Tk = td;
            } else if (parameters_.fixed_overlap >= 0.0) {
                Tk = std::min(parameters_.fixed_overlap, Tk_max);
                report.Tk_tolerance = parameters_.fixed_overlap;
            } else {
                Tk = solve_overlap(model, last_.tolerance, parameters_.tolerance_meaning, period, Tk_max);
                report.Tk_tolerance = Tk;
                if (Tk == Tk_max && Tk_max < td)  // report-only: what the clamp took away
                    report.Tk_tolerance = solve_overlap(model, last_.tolerance, parameters_.tolerance_meaning, period, td);
            }
        }
        start = schedule(Tk, now, Tk == 0.0 && !report.exact_stop, report.exact_stop ? dwell : 0.0);
        joined = joined && start.Tk == td;
        report.Tk = start.Tk;
        if (!joined && !report.exact_stop) {  // report-only
            const CornerModel model{chain_, last_.run_delta, last_.run_tv, delta, tv};
            report.predicted_error = parameters_.tolerance_meaning == ToleranceMeaning::contour
                                         ? model.contour_error(start.Tk)
                                         : model.corner_error(start.Tk);
        }
        report.speed_in = last_.feed;
        report.speed_out = feed;
        report.bound = report.exact_stop ? CornerBound::stop
                       : start.Tk >= td  ? CornerBound::feed
                                         : CornerBound::tolerance;
    }

    const Leg leg = candidate(delta, length, feed, start, block);
    if (!timeline_->push(leg)) return Result::queue_full;
    ++pushed_;
    if (feed < block.feed) ++stats_.slowed;
    if (feed < block.feed * crawl_fraction) ++stats_.crawling;

    Last next = last_;
    next.end = block.target;
    next.feed = feed;
    next.termination = block.termination;
    next.tolerance = block.termination == Termination::blend ? block.tolerance : std::numeric_limits<double>::infinity();
    next.line = block.line;
    next.moving = true;
    next.end_tick = leg.rise_tick;
    next.end_offset = leg.rise_offset + tv;
    normalise(next.end_tick, next.end_offset, period);
    if (joined) {
        next.run_delta = last_.run_delta + delta;
        next.run_tv = last_.run_tv + tv;
        next.Tk_in = last_.Tk_in;
    } else {
        next.run_delta = delta;
        next.run_tv = tv;
        next.Tk_in = start.Tk;
    }
    const bool formed_corner = last_.moving;
    if (formed_corner && !joined && !report.exact_stop && std::isfinite(last_.tolerance)) {
        // Later pulses may still move this corner while its overlap lasts.
        const double end = static_cast<double>(last_.end_tick) * period + last_.end_offset;  // on the timeline's clock
        const double rise = static_cast<double>(leg.rise_tick) * period + leg.rise_offset;
        if (corner_count_ == corners_.size()) {
            std::move(corners_.begin() + 1, corners_.end(), corners_.begin());
            --corner_count_;
        }
        corners_[corner_count_++] = {last_.end, last_.tolerance, pushed_ - 2, end + td, 0.5 * (rise + end + td)};
    }
    // Corners whose overlap has passed can no longer move.
    while (corner_count_ > 0 && corners_[0].window_end < static_cast<double>(leg.rise_tick) * period + leg.rise_offset) {
        std::move(corners_.begin() + 1, corners_.begin() + static_cast<std::ptrdiff_t>(corner_count_), corners_.begin());
        --corner_count_;
    }
    last_ = next;
    if (formed_corner) {
        reports_[(report_head_ + report_count_) % reports_.size()] = report;
        if (report_count_ < reports_.size()) ++report_count_;
        else report_head_ = (report_head_ + 1) % reports_.size();
    }
    return Result::ok;
}

}  // namespace firtp
