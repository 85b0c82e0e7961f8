// The look-ahead's plan as motion: its steps and legs, the checks, and freezing steps onto the
// timeline as their kernels start.
#include <firtp/lookahead.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>

namespace firtp {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr int max_check_attempts = 12;
constexpr double check_backoff = 0.9;  // a failed corner's speed is lowered by at least this factor
constexpr double crawl_fraction = 1e-3;
// check()'s *bad when the block under way cannot take the new plan (no corner to lower).
constexpr std::size_t front_unfit = static_cast<std::size_t>(-1);

}  // namespace

double Lookahead::start_after_stop(std::size_t i, double stop, const Step& stop_step, double half) const {
    // A sample lands on the corner while the tool rests (and the dwell runs on the tick grid).
    return on_tick_grid(stop + 0.5 * stop_step.kernel.width() + seg(i).dwell) + half;
}

double Lookahead::on_tick_grid(double t) const {
    const double period = parameters_.period;
    return std::ceil(t / period - 1e-9) * period;
}

double Lookahead::frozen_centre() const {
    return static_cast<double>(frozen_.tick - timeline_->now()) * parameters_.period + frozen_.offset;
}

Lookahead::NextStep Lookahead::next_step() const {
    const Segment& s = seg(0);
    const double period = parameters_.period;
    NextStep n;
    if (!frozen_.moving) {  // the start step of the front segment, as early as allowed
        n.step = entry_step(0);
        n.kind = StepKind::start;
        n.speed_after = s.a;
        const double half = 0.5 * n.step.kernel.width();
        n.centre = half;  // its kernel starts now
        if (frozen_.any) {
            const double stop = frozen_centre();
            n.centre = std::max(n.centre, stop + rules_.spacing(frozen_.step.shape(), n.step.shape()));
            n.centre = std::max(n.centre, stop + frozen_.rest);
            n.centre = std::max(n.centre, start_after_stop(0, stop, frozen_.step, half));
            // Every kernel still under way must have settled too: a hold's stop may fall inside
            // the wider kernel of the step before it, which then ends after the stop's.
            for (std::size_t k = 0; k < timeline_->size(); ++k) {
                const Leg& leg = timeline_->at(k);
                n.centre = std::max(n.centre, on_tick_grid(leg.finish() - timeline_->local_time(leg, timeline_->now())) + half);
            }
        } else if (s.dwell > 0.0) {  // from rest: the dwell runs from when the block came
            const double since = s.added - static_cast<double>(timeline_->now()) * period;
            n.centre = std::max(n.centre, on_tick_grid(since + s.dwell) + half);
        }
        return n;
    }
    n.centre = frozen_centre() + s.x0;
    if (s.p != s.a) {
        n.step = in_ramp_step(0, s.p - s.a);
        n.speed_after = s.p;
    } else if (s.b != s.p) {
        n.step = out_ramp_step(0, s.b - s.p);
        n.speed_after = s.b;
    } else if (count_ == 1 || s.kind == Kind::stop) {
        n.step = stop_step(0);
        n.kind = StepKind::stop;
        n.speed_after = 0.0;
        return n;
    } else {
        n.step = junction_step(0);
        n.kind = StepKind::junction;
        n.speed_after = s.next_a;
        return n;
    }
    n.kind = StepKind::ramp;
    return n;
}

bool Lookahead::final_for_start() const {
    // A window with blocks waiting beyond its reach (deferred_) is as long as a plan needs, as a
    // full one is; one still filling is not.
    if (filling_ && deferred_ > 0) return front_final();
    if (finished_ || deferred_ > 0 || count_ >= capacity_) return true;
    return front_final();
}

bool Lookahead::front_final() const {
    if (seg(0).exit_end_limited) return false;
    if (count_ >= 2 && seg(0).kind == Kind::dense && seg(1).entry_end_limited) return false;
    // A run of dense blocks keeps one speed a block: a slow junction further on can slow it more
    // than the stop at the end of the known path does. The start waits until the run's end is known.
    for (std::size_t k = 0; k < count_; ++k) {
        const Segment& s = seg(k);
        if (!s.dense || s.kind == Kind::stop) return settled(k);
    }
    return false;
}

void Lookahead::refresh_current_leg() {
    if (!frozen_.moving || timeline_->idle() || count_ == 0) return;
    const Segment& s = seg(0);
    const NextStep n = next_step();
    const double centre = frozen_centre();
    Leg& leg = timeline_->back();
    leg.tv = n.centre - centre;
    const double length = frozen_.speed * leg.tv;
    leg.delta = s.u * length;
    const bool overlap = n.kind == StepKind::junction && split(0);  // the leg across the corner ends the block
    leg.end = n.kind == StepKind::ramp ? AxisVector(s.start + s.u * (frozen_.consumed + length))
                                       : AxisVector(s.end - s.u * (overlap ? s.overlap_at(s.b) : 0.0));
    leg.last_of_block = n.kind != StepKind::ramp && !s.hold_split && !overlap;  // a hold's split is not the block's end
    leg.fall = (n.centre - 0.5 * n.step.kernel.width()) - (centre - 0.5 * frozen_.step.kernel.width());
    leg.falling = n.step.kernel;
    max_width_ = std::max(max_width_, n.step.kernel.width());
    timeline_->widen(max_width_);
}

void Lookahead::pop_front(bool stop) {
    Segment& s = seg(0);
    const double fastest = std::max({s.a, s.p, s.b});
    if (!s.hold_split) {  // a hold's stop is neither a corner nor a slow block
        if (fastest < s.feed * (1.0 - 1e-9)) ++stats_.slowed;
        if (fastest < s.feed * crawl_fraction) ++stats_.crawling;
    }
    const bool last = count_ == 1 && deferred_ == 0;  // the program's last block, as far as it is known
    if ((!last || stop) && !s.hold_split) {  // the junction after it is decided: report it
        CornerReport r;
        r.line = s.line;
        r.point = s.end;
        r.beta = s.turn.beta;
        r.speed_in = s.b;
        r.speed_out = count_ > 1 && s.kind != Kind::stop ? s.next_a : 0.0;
        r.epsilon = s.tolerance;
        r.exact_stop = s.kind == Kind::stop || count_ == 1;  // (a window a change cut ends in a stop)
        r.predicted_error = s.exact_stop || r.exact_stop ? 0.0 : s.predicted_error;
        r.bound = r.exact_stop ? stop_bound(s) : s.bound;
        r.axis = s.bound_axis;
        r.Tk = r.exact_stop ? 0.0 : s.overlap_time();
        if (!last) {  // the end of the program is not a corner
            reports_[(report_head_ + report_count_) % reports_.size()] = r;
            if (report_count_ < reports_.size()) ++report_count_;
            else report_head_ = (report_head_ + 1) % reports_.size();
        }
    }
    head_ = (head_ + 1) % segments_.size();
    --count_;
    for (std::size_t* change : {&ramp_change_, &regime_change_})
        if (*change != static_cast<std::size_t>(-1) && *change > 0) --*change;
    if (join_.open) join_popped();
}

bool Lookahead::take_report(CornerReport& report) {
    if (report_count_ == 0) return false;
    report = reports_[report_head_];
    report_head_ = (report_head_ + 1) % reports_.size();
    --report_count_;
    return true;
}

void Lookahead::freeze(const NextStep& n) {
    next_known_ = false;
    join_.froze = join_.froze || join_.open;  // (a ramp's freeze changes the front segment too)
    const double period = parameters_.period;
    const Segment& front = seg(0);
    // The new frozen step's centre, on the tick grid.
    std::int64_t tick = timeline_->now();
    double offset = n.centre;
    normalise(tick, offset, period);
    const AxisVector leg_start = n.kind == StepKind::ramp ? AxisVector(front.start + front.u * (frozen_.consumed + frozen_.speed * front.x0))
                                                          : n.kind == StepKind::start ? front.start : front.end;
    switch (n.kind) {
        case StepKind::ramp: {
            frozen_.consumed += frozen_.speed * front.x0;
            // The segment's plan now starts at this step: its first leg is done.
            Segment& s = seg(0);
            if (s.p != s.a && s.b != s.p) {  // the cruise, then the ramp to b
                s.a = s.p;
                s.x0 = s.xp;
                s.xp = 0.0;
            } else {  // one leg left, at the speed this ramp reached
                s.a = s.p = s.b;
                s.x0 = s.x1;
                s.xp = s.x1 = 0.0;
            }
            // Braked to rest at the block's very end (a hold, hold_end): the block is done. (Kept,
            // it had no length left to start again from rest, and a resume spun on a start at
            // speed 0.)
            if (!(s.b > 0.0) && !(s.length - frozen_.consumed > 1e-12 * s.length)) {
                frozen_.rest = front.rest;
                pop_front(true);
                frozen_.consumed = 0.0;
            }
            break;
        }
        case StepKind::junction:
            if (split(0)) return freeze_overlap(n, tick, offset);
            pop_front(false);
            frozen_.consumed = 0.0;
            break;
        case StepKind::stop:
            frozen_.rest = front.rest;
            pop_front(true);
            frozen_.consumed = 0.0;
            break;
        case StepKind::start:
            frozen_.consumed = 0.0;
            break;
    }
    frozen_.any = true;
    frozen_.start = n.kind == StepKind::start;
    enter_front(n.step, tick, offset, n.speed_after, n.kind == StepKind::junction, leg_start);
}

// The two steps of an overlapped corner freeze together when the first one's kernel starts: the
// leg across the corner (the block's last) goes to the timeline, and the second step, Tk later,
// becomes the frozen one, entering the next block `overlap` along it.
void Lookahead::freeze_overlap(const NextStep& n, std::int64_t tick, double offset) {
    const Segment& s = seg(0);
    const Step fall = overlap_fall(0);
    const double overlap = s.overlap_at(s.b), tk = s.overlap_time();
    Leg leg;
    leg.rising = n.step.kernel;
    leg.falling = fall.kernel;
    leg.rise_tick = tick;
    leg.rise_offset = offset - 0.5 * n.step.kernel.width();
    normalise(leg.rise_tick, leg.rise_offset, parameters_.period);
    leg.tv = tk;
    leg.fall = tk + 0.5 * (n.step.kernel.width() - fall.kernel.width());
    leg.delta = overlap_delta(0);
    leg.end = s.end + seg(1).u * overlap;
    leg.line = s.line;
    leg.type = s.type;
    leg.last_of_block = true;
    max_width_ = std::max({max_width_, n.step.kernel.width(), fall.kernel.width()});
    timeline_->widen(max_width_);
    timeline_->push(leg);
    ++stats_.overlapped;
    pop_front(false);
    frozen_.consumed = overlap;
    frozen_.any = true;
    frozen_.start = false;
    offset += tk;
    normalise(tick, offset, parameters_.period);
    enter_front(fall, tick, offset, n.speed_after, true, leg.end);
}

void Lookahead::enter_front(const Step& step, std::int64_t tick, double offset, double speed, bool junction, const AxisVector& leg_start) {
    const double period = parameters_.period;
    frozen_.step = step;
    frozen_.tick = tick;
    frozen_.offset = offset;
    frozen_.speed = speed;
    frozen_.junction = junction;
    frozen_.moving = speed > 0.0 && count_ > 0;
    if (!frozen_.moving) return;
    const Segment& s = seg(0);
    Leg leg;
    leg.rising = step.kernel;
    std::int64_t rise_tick = tick;
    double rise_offset = offset - 0.5 * step.kernel.width();
    normalise(rise_tick, rise_offset, period);
    leg.rise_tick = rise_tick;
    leg.rise_offset = rise_offset;
    leg.line = s.line;
    leg.type = s.type;
    leg.end = leg_start;  // refresh_current_leg sets delta, tv, end and the falling edge
    max_width_ = std::max(max_width_, step.kernel.width());
    timeline_->widen(max_width_);
    timeline_->push(leg);
    refresh_current_leg();
}

void Lookahead::find_next(double now) const {
    const NextStep n = next_step();
    next_start_ = now + n.centre - 0.5 * n.step.kernel.width();
    next_is_start_ = n.kind == StepKind::start;
    next_known_ = true;
}

bool Lookahead::start_due() const {
    return count_ > 0 && !held_ && !batch_.open && next_due() && next_is_start_;
}

void Lookahead::plan_batch() {
    Batch& b = batch_;
    b.open = false;
    if (count_ == b.count) return;  // only skipped blocks: their dwell waits for the next
    // The bounds and the plan once for the batch.
    if (plan_joined(b.count, b.blocks.size() > 1)) return;
    // Undone: the window as the batch found it, and its blocks added one by one.
    head_ = b.head, count_ = b.count, goal_ = b.goal;
    for (std::size_t i = 0; i < count_; ++i) seg(i) = b.window[i];
    pending_dwell_ = b.pending_dwell, finished_ = b.finished;
    restore(b.plan);
    ++stats_.batches_undone;
    for (const Block& block : b.blocks) add(block, Planning::now);
}

void Lookahead::commit() {
    if (join_.open) {
        ++stats_.join_steps;
        join_step(false);
    }
    if (batch_.open) plan_batch();
    const double period = parameters_.period;
    if (retry_ && count_ > 0) {  // a hold's stop or a resume that failed its check: again from here
        finish_join();
        retry_ = false;
        replan_from_front(!held_);
    }
    rejoin_some();
    for (;;) {
        if (count_ == 0) return;
        // The next step's kernel start is kept until the plan changes: most ticks end here.
        if (!next_due()) {
            if (!next_is_start_) waiting_since_ = -1;
            return;
        }
        // A join's next step would change what this freeze reads or leaves near the front, or the
        // flags a start asks for (final_for_start).
        if (join_.open && (next_is_start_ || join_front() < join_split_from)) {
            ++stats_.joins_hurried;
            finish_join();
            continue;
        }
        if (next_is_start_) {
            if (held_ || retry_) return;  // (a resume not yet checked: the plan after the stop is not)
            if (waiting_since_ < 0) waiting_since_ = timeline_->now();
            const bool idle = parameters_.start_idle > 0.0 &&
                              static_cast<double>(timeline_->now() - last_add_tick_) * period >= parameters_.start_idle;
            const bool stalled = idle || static_cast<double>(timeline_->now() - waiting_since_) * period >= parameters_.start_wait;
            if (!final_for_start() && !stalled) return;
            waiting_since_ = -1;
        }
        freeze(next_step());
        // A batch's undo restores the window as the join found it: the front as it is now.
        if (join_.open && join_.undoable && count_ > 0) snapshot_[join_.pops] = seg(0);
    }
}

// ---- Checking a plan ---------------------------------------------------------------------------

void Lookahead::build_legs(std::size_t first) {
    legs_.clear();
    // Times in seconds from the timeline's now. Segment 0 starts at the frozen step (moving) or
    // at its start step.
    double t = frozen_.moving ? frozen_centre() : next_step().centre;
    for (std::size_t i = 0; i < first; ++i) t += span(seg(i));
    if (first == 0)
        for (std::size_t k = 0; k < timeline_->size(); ++k) {
            if (frozen_.moving && k + 1 == timeline_->size()) break;  // the current leg: from the plan below
            const Leg& leg = timeline_->at(k);
            TimedLeg tl;
            tl.delta = leg.delta;
            tl.tv = leg.tv;
            tl.rise = -timeline_->local_time(leg, timeline_->now());
            tl.fall = leg.fall;
            tl.rising = leg.rising;
            tl.falling = leg.falling;
            legs_.push_back(tl);
        }
    Step last_step;  // the step the previous block's legs ended on
    for (std::size_t i = first; i < count_; ++i) {
        Segment& s = seg(i);
        enter_[i] = t;
        leg_begin_[i] = legs_.size();
        // After a junction the entry step is the junction step the block before ended on
        // (entry_step(i) = junction_step(i - 1), the same arithmetic): kept, not made again.
        Step step = i > first && !entry_is_stop(i) ? last_step : entry_step(i);
        double centre = t, speed = s.a;
        // The leg from the current step to the next, at the current speed.
        auto leg_to = [&](const Step& next, double next_centre) {
            if (speed > 0.0 && next_centre > centre) {
                TimedLeg tl;
                tl.tv = next_centre - centre;
                tl.delta = s.u * (speed * tl.tv);
                tl.rise = centre - 0.5 * step.kernel.width();
                tl.fall = (next_centre - 0.5 * next.kernel.width()) - tl.rise;
                tl.rising = step.kernel;
                tl.falling = next.kernel;
                legs_.push_back(tl);
            }
            step = next;
            centre = next_centre;
        };
        if (s.p != s.a) {
            leg_to(in_ramp_step(i, s.p - s.a), t + s.x0);
            speed = s.p;
        }
        if (s.b != s.p) {
            leg_to(out_ramp_step(i, s.b - s.p), t + s.x0 + s.xp);
            speed = s.b;
        }
        const bool stop = i + 1 == count_ || s.kind == Kind::stop;
        leg_to(stop ? stop_step(i) : junction_step(i), t + s.x0 + s.xp + s.x1);
        when_[i] = centre;
        if (!stop && split(i)) {  // the leg across the corner, then the pulse falls
            const Step fall = overlap_fall(i);
            const double tk = s.overlap_time();
            TimedLeg tl;
            tl.tv = tk;
            tl.delta = overlap_delta(i);
            tl.rise = centre - 0.5 * step.kernel.width();
            tl.fall = (centre + tk - 0.5 * fall.kernel.width()) - tl.rise;
            tl.rising = step.kernel;
            tl.falling = fall.kernel;
            legs_.push_back(tl);
            when_[i] = centre + 0.5 * tk;  // the middle of that leg (the closest approach's guess)
            step = fall;
            centre += tk;
        }
        last_step = step;
        leg_of_[i] = legs_.empty() ? 0 : legs_.size() - 1;
        t = centre + (stop ? s.rest : 0.0);
        s.width = 0.0;
        for (std::size_t m = leg_begin_[i]; m < legs_.size(); ++m)
            s.width = std::max({s.width, legs_[m].rising.width(), legs_[m].falling.width()});
        width_bound_ = std::max(width_bound_, s.width);
    }
    index_legs(legs_);
}

bool Lookahead::same_motion(const Segment& s, const Segment& before) {
    return !before.unchecked && s.a == before.a && s.p == before.p && s.b == before.b && s.x0 == before.x0 && s.xp == before.xp &&
           s.x1 == before.x1 && s.rest == before.rest && s.next_a == before.next_a && s.kind == before.kind &&
           s.planned_stop == before.planned_stop && s.u == before.u && s.regime == before.regime && s.junction == before.junction &&
           s.in_ramp == before.in_ramp && s.out_ramp == before.out_ramp;
}

double Lookahead::first_kernel_start(std::size_t from, std::size_t k, std::size_t legs) const {
    // A segment's steps are the kernels of its legs (a leg rises on one step, falls on the next);
    // the step entering k is also the falling one of the leg before (k may have none).
    const std::size_t begin = k > from ? leg_begin_[k] : 0;
    double earliest = begin > 0 && begin <= legs ? legs_[begin - 1].rise + legs_[begin - 1].fall : infinity;
    for (std::size_t m = begin; m < legs; ++m) earliest = std::min({earliest, legs_[m].rise, legs_[m].rise + legs_[m].fall});
    return earliest;
}

std::size_t Lookahead::context(std::size_t first) const {
    // A first guess: as far back as the last check needed (covered_from() then widens it as far
    // as the legs left out still move).
    std::size_t from = first;
    double back = 0.0;
    while (from > 0 && back < context_span_) back += span(seg(--from));
    return from;
}

std::size_t Lookahead::covered_from(std::size_t from, std::size_t first, double until) {
    // Left out of a check from k > 0: the timeline's legs, and those of the segments before k,
    // each of which ends by the next segment's entry plus half its widest kernel.
    for (std::size_t k = 0; k < timeline_->size(); ++k) {
        const Leg& leg = timeline_->at(k);
        if (!(leg.finish() - timeline_->local_time(leg, timeline_->now()) < until)) return 0;
    }
    for (std::size_t j = from; j < first; ++j) settled_by_[j] = enter_[j + 1] + 0.5 * seg(j).width;
    double t = enter_[from];  // this build's
    // Going back, t only falls: once a segment has come to rest by `until` even at the widest
    // width any segment has, so have all before it, and the scan starts after it (walking back to
    // the front cost 9 % of an add with 4096 blocks waiting). The same answer as from 0.
    std::size_t k = 0;
    for (std::size_t j = from; j-- > 0;) {
        if (t + 0.5 * width_bound_ < until) {
            k = j + 1;
            break;
        }
        const Segment& s = seg(j);
        settled_by_[j] = t + 0.5 * s.width;
        t -= span(s);
    }
    while (k < first && settled_by_[k] < until) ++k;
    return k;
}

bool Lookahead::check(std::size_t first, std::size_t changed, std::size_t* bad) {
    CheckRun c;
    Checked result = check_begin(first, changed, bad, c);
    if (result == Checked::corners) result = check_corners(c, static_cast<std::size_t>(-1), bad);
    return result == Checked::passed;
}

bool Lookahead::check_measures(const CheckRun& c, std::size_t i) const {
    const Segment& s = seg(i - c.shift);
    return s.kind != Kind::stop && s.turn.beta >= straight_angle && std::isfinite(s.tolerance) &&
           when_[i] + s.checked_reach >= c.unchanged_until;
}

Lookahead::Checked Lookahead::check_begin(std::size_t first, std::size_t changed, std::size_t* bad, CheckRun& c) {
    c = CheckRun{};  // (a join's: segments may have left the window since it opened, none since this build)
    limit_failure_ = {};
    std::size_t from = context(first);
    // Held: what follows the hold's stop starts only after a resume, which plans and checks it
    // again; the check ends at the stop.
    const std::size_t stop = held_ ? hold_stop_index() : count_;
    const std::size_t last = stop < count_ ? stop + 1 : count_;
    if (first >= last) return Checked::passed;
    // A block its legs do not cover: lower the corner it is entered from.
    for (std::size_t i = first; i < last; ++i) {
        if (!seg(i).unfit) continue;
        if (i > 0 && seg(i - 1).kind != Kind::stop) {
            excess_ = 0.0;
            *bad = i - 1;
            return Checked::failed;
        }
        if (i == 0 && frozen_.moving) {  // a new feed (or a hold's braking) the motion under way cannot take
            *bad = front_unfit;
            return Checked::failed;
        }
        ++stats_.unfit;  // entered from rest: a defect
    }
    // The next step freezes when its kernel starts: a plan whose kernel starts before the last
    // sample already sent (one period before now) would jump. No corner to lower for it: replan()
    // keeps the accepted plan (a rate change tries again at the next tick; a new block starts
    // from rest after it).
    if (first == 0 && frozen_.moving) {
        const NextStep n = next_step();
        if (n.centre - 0.5 * n.step.kernel.width() < -(1.0 + 1e-9) * parameters_.period) {
            *bad = count_ - 1;
            return Checked::failed;
        }
    }
    double end = 0.0;
    double width = 0.0;  // the widest kernel of these legs: the reach of a change among them
    bool sharp = false;  // a step without stages jumps in velocity: no acceleration bounds its chords
    bool one_stage = false;  // ... one stage jumps in acceleration: no jerk bounds it
    std::size_t legs = 0;
    double begin = 0.0, sweep_from = 0.0;
    // Every corner the changed motion can reach. The motion changes from the step entering
    // `changed` on (the legs after it and the junction step before it): nothing moves differently
    // before its widest kernel starts, nor before the first of their kernels does (2 periods to
    // spare). A corner whose last check looked only before that passed on this very motion.
    double& unchanged_until = c.unchanged_until;
    auto measured = [&](std::size_t i) { return check_measures(c, i); };
    const bool contour = parameters_.tolerance_meaning == ToleranceMeaning::contour;
    for (;;) {
        build_legs(from);
        end = enter_[first], width = 0.0, sharp = false, one_stage = false;
        legs = last < count_ ? leg_of_[last - 1] + 1 : legs_.size();
        for (std::size_t k = 0; k < legs; ++k) {
            const TimedLeg& leg = legs_[k];
            end = std::max(end, leg.finish());
            width = std::max({width, leg.rising.width(), leg.falling.width()});
            sharp = sharp || leg.rising.width() == 0.0 || leg.falling.width() == 0.0;
            one_stage = one_stage || !(leg.rising.b > 1e-9 * leg.rising.a) || !(leg.falling.b > 1e-9 * leg.falling.a);
        }
        max_width_ = std::max(max_width_, width);
        // What ran before now is done (and retired legs are gone from the timeline).
        begin = std::max(enter_[first] - max_width_, 0.0);
        // Planning from `first` changes the steps from the one entering first - 1 on (the junction
        // fields of first - 1 are set with it, and the junction regime before it). Before the
        // earliest of their kernels starts, the sums are those an accepted plan's check swept: the
        // sweep starts there (`begin` reaches the widest kernel of the whole program back). Not
        // from the front, nor over blocks a fallback left unchecked.
        // Held, the legs after the hold's stop are the resume's plan, not motion: only those up to it
        // (they had cancelled a hold's braking against the resume's start: 2x an axis' acceleration).
        bool checked_before = first > from;
        for (std::size_t i = from; i < first && checked_before; ++i) checked_before = !seg(i).unchecked;
        sweep_from = checked_before ? std::max(begin, std::min(first_kernel_start(from, first - 1, legs), end)) : begin;
        unchanged_until = infinity;
        if (changed < count_) {
            unchanged_until = enter_[changed] - 0.5 * width;
            if (changed > from) unchanged_until = std::max(unchanged_until, first_kernel_start(from, changed, legs));
            unchanged_until -= 2.0 * parameters_.period;
        }
        // The legs left out (before `from`) must have come to rest before the sweep starts and
        // before any corner's measurement looks: a step at the context's edge rising alone is a
        // jump of its leg's whole speed (1.2e9 mm/s^3 over a 0.14 ms stage: a false refusal,
        // random program 422 of seed 31). The context is only as wide as the kernels that still
        // move there: a rapid's, 10x a dense run's, no longer widens every check after it.
        double until = sweep_from;
        const double look_back = contour ? contour_reach(max_width_, parameters_.period) : approach_reach(parameters_.period);
        for (std::size_t i = from; i + 1 < last; ++i)
            if (measured(i)) until = std::min(until, when_[i] - look_back);
        const std::size_t covered = covered_from(from, first, until);
        if (covered >= from) {
            context_span_ = enter_[first] - enter_[covered];
            break;
        }
        from = covered;
    }
    ++stats_.checks;
    stats_.legs_checked += legs;
    LimitCheck limits = sweep_.check(std::span<const TimedLeg>(legs_.data(), legs), sweep_from, end, machine_, parameters_.period);
    limit_failure_ = limits;
    // Steps freeze when their kernels start, in order: a leg's falling kernel may not start before
    // its rising one (the spacing rules keep that; dense runs and their stops are checked here).
    order_failure_ = false;
    for (std::size_t k = 0; k < legs && limits.ok; ++k)
        if (legs_[k].fall < -1e-12) limits = {false, legs_[k].fall_centre, 0, 0, 0.0}, order_failure_ = true;
    excess_ = 0.0;
    if (!limits.ok) {  // lower the corner nearest to where it happened
        std::size_t nearest = count_;
        double distance = infinity;
        for (std::size_t i = from; i + 1 < last; ++i) {
            if (seg(i).kind == Kind::stop) continue;
            const double d = std::abs(when_[i] - limits.time);
            if (d < distance) distance = d, nearest = i;
        }
        *bad = nearest;
        return Checked::failed;
    }
    c.from = from, c.last = last, c.next = from;
    c.begin = begin, c.sharp = sharp, c.one_stage = one_stage;
    return Checked::corners;
}

Lookahead::Checked Lookahead::check_corners(CheckRun& c, std::size_t most, std::size_t* bad) {
    const bool contour = parameters_.tolerance_meaning == ToleranceMeaning::contour;
    for (; c.next + 1 < c.last && most > 0; ++c.next) {
        const std::size_t i = c.next;  // (legs_, when_ and leg_of_ as the check built them)
        if (!check_measures(c, i)) continue;
        --most;
        Segment& s = seg(i - c.shift);
        if (contour) {  // the samples across the corner
            double latest = 0.0;
            s.predicted_error = contour_error(legs_, leg_of_[i], when_[i], max_width_, parameters_.period, &latest);
            s.checked_reach = latest - when_[i];
        } else {
            // Where the sweep above covered the approach (Newton moves at most 24 periods), the
            // chords' sag is bounded by the limits it held.
            const double period = parameters_.period;
            ApproachBounds bounds;
            if (!c.sharp && when_[i] - 32.0 * period >= c.begin)
                bounds = {machine_acceleration_, c.one_stage ? HUGE_VAL : machine_jerk_, s.tolerance * (1.0 - check_margin)};
            // (Overlapped, the leg across the corner ends `overlap` along the next block.)
            const std::size_t k = i - c.shift;
            const AxisVector offset = split(k) ? AxisVector(-s.overlap_at(s.b) * seg(k + 1).u) : AxisVector(AxisVector::Zero());
            const Approach approach = closest_approach(legs_, leg_of_[i], when_[i], period, 1, bounds, offset);
            s.predicted_error = approach.distance;
            s.checked_reach = approach.latest - when_[i];
        }
        const double epsilon = s.tolerance * (1.0 - check_margin);
        excess_ = s.predicted_error / epsilon;
        if (s.predicted_error > epsilon) {
            *bad = i - c.shift;
            return Checked::failed;
        }
    }
    return c.next + 1 < c.last ? Checked::corners : Checked::passed;
}

bool Lookahead::replan(std::size_t first, bool undoable) {
    Replan r;
    if (!replan_begin(first, r)) return true;
    return replan_run(r, undoable);
}

bool Lookahead::replan_begin(std::size_t first, Replan& r) {
    next_known_ = false;
    first = std::min(first, take_ramp_change());
    // Under way, a failed change falls back on the accepted plan (at rest there is nothing to keep).
    r.fallback = frozen_.moving && (snapshot_taken_ || (held_ && !hold_stop_placed()));
    if (held_ && frozen_.moving && !hold_stop_placed()) {
        if (!snapshot_taken_) take_snapshot();
        place_hold_stop();
        first = 0;
        take_ramp_change();
    }
    snapshot_taken_ = false;
    if (first >= count_) {
        refresh_current_leg();
        return false;
    }
    // The accepted plan, restored if no change passes the check: [first - 1, count) now (planning
    // segment `first` sets the junction fields of the one before), the rest on the first failure
    // (untouched until then).
    r.kept = first > 0 ? first - 1 : 0;
    for (std::size_t i = r.kept; i < count_; ++i) saved_[i] = seg(i);
    r.saved_all = r.kept == 0;
    r.from = first;
    r.attempt = 0;
    r.lowered = count_;
    return true;
}

void Lookahead::replan_forward(Replan& r) {
    forward(r.from);
    // The check starts where the motion changed: the backward pass also goes back over blocks
    // whose speeds it found unchanged (their end-of-path flags flipped), and forward() plans
    // them again to the same legs, which were checked (a whole queue of 256 blocks re-checked
    // at one add of examples/polygon360.ngc).
    r.changed = r.from;
    if (r.attempt == 0 && !held_ && frozen_.moving)  // (at rest the start moves with the clock)
        while (r.changed < count_ && same_motion(seg(r.changed), saved_[r.changed])) ++r.changed;
}

void Lookahead::replan_passed(const Replan& r) {
    for (std::size_t i = r.changed; i < count_; ++i) seg(i).unchecked = false;
}

bool Lookahead::replan_run(Replan& r, bool undoable) {
    for (;;) {
        replan_forward(r);
        std::size_t bad = count_;
        if (check(r.from, r.changed, &bad)) {
            replan_passed(r);
            break;
        }
        const Remedy remedy = replan_failed(r, bad, undoable);
        if (remedy == Remedy::undo) return false;
        if (remedy == Remedy::kept) return true;
        if (remedy == Remedy::planned) break;
        ++r.attempt;
    }
    replan_end(r.from);
    return true;
}

Lookahead::Remedy Lookahead::replan_failed(Replan& r, std::size_t bad, bool undoable) {
    ++stats_.checks_failed;
    // The same limit failed at the same moment by the same amount: lowering that corner did
    // not touch it, nor will lowering it further (a change retried at every tick lowered the
    // same corner 0.9x a try until the tool crawled: RateChange seed 77 program 51).
    const LimitCheck& f = limit_failure_;
    auto near = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max({std::abs(x), std::abs(y), 1.0}); };
    const bool futile = r.fallback && r.lowered < count_ && !f.ok && !r.lowered_for.ok && f.axis == r.lowered_for.axis &&
                        f.derivative == r.lowered_for.derivative && near(f.time, r.lowered_for.time) &&
                        near(f.value, r.lowered_for.value);
    if (futile) seg(r.lowered).learned_cap = r.lowered_cap;
    r.lowered = count_;
    std::size_t& from = r.from;
    // Nothing left to lower: what is kept instead depends on who asked.
    const bool no_plan = futile || bad == front_unfit || r.attempt == max_check_attempts || bad + 1 >= count_;
    // A batch with no plan short of the last resort: undone (plan_added). (Nothing after the
    // first attempt reads saved_ for a batch: a join's may be from before steps froze.)
    if (undoable && no_plan) return Remedy::undo;
    if (r.fallback && no_plan) {
        // No plan after the hold's or the resume's change passes: the accepted one goes on
        // (never an unchecked one) and the change is tried again at the next tick, from the
        // corners this try lowered (each retry made the same 13 attempts again, 3 ms a tick
        // with 256 blocks waiting: tests/soak).
        const bool same_blocks = count_ == snapshot_count_;
        for (std::size_t i = 0; same_blocks && i < snapshot_count_; ++i) {
            const Segment& s = seg(i);
            if (s.line == snapshot_[i].line && s.end == snapshot_[i].end)
                snapshot_[i].learned_cap = std::min(snapshot_[i].learned_cap, s.learned_cap);
        }
        // (A hold's split moved the ring's head; the blocks the change left out come back as
        // they were, after the kept ones.)
        head_ = snapshot_head_;
        for (std::size_t i = 0; i < snapshot_count_; ++i) seg(i) = snapshot_[i];
        count_ = snapshot_count_ + snapshot_cut_;
        deferred_ -= snapshot_cut_;
        snapshot_cut_ = 0;
        retry_ = true;
        refresh_current_leg();
        return Remedy::kept;
    }
    if (!r.saved_all) {
        for (std::size_t i = 0; i < r.kept; ++i) saved_[i] = seg(i);
        r.saved_all = true;
    }
    if (no_plan) {  // (futile only where there is a fallback: it returned above)
        // Keep the plan accepted before (it stopped where the path ended then) and start the
        // newest block from rest after it. Also where the block under way cannot take the new
        // plan (front_unfit): restoring the accepted plan alone left the newest block unplanned,
        // at speed 0, and the tool rested there for good (lcnc__tort.ngc, its line 95).
        for (std::size_t i = 0; i + 1 < count_; ++i) seg(i) = saved_[i];
        if (count_ >= 2) {
            // It was the last block: as it was classified then (adding the newest changed that).
            seg(count_ - 2).forced_stop = true;
            junction_caps(count_ - 2);
            classify(count_ - 2);
            if (count_ >= 3) junction_caps(count_ - 3);
        }
        backward(count_ - 1);
        from = std::min(count_ >= 2 ? count_ - 2 : 0, take_ramp_change());
        // At rest, a plan restored from a hold brakes to a standstill and cannot start again
        // (machine 61, program 1689): nothing is under way to keep, so from rest again.
        if (!frozen_.moving && !(seg(0).a > 0.0)) from = 0;
        forward(from);
        // Not built as planned now: as wide as any kernel checked so far, for context().
        for (std::size_t i = from; i < count_; ++i) seg(i).unchecked = true, seg(i).width = std::max(seg(i).width, max_width_);
        width_bound_ = std::max(width_bound_, max_width_);
        return Remedy::planned;
    }
    // A limit failed next to ramps sharing a corner's jerk stage at J T2: an axis swings the
    // other way within it whatever the speed. They keep the run's caps (h = J T2 / 2).
    if (excess_ == 0.0 && seg(bad).ramps_capped && seg(bad).kind == Kind::corner && !seg(bad).junction.sparse) {
        seg(bad).ramps_capped = false;
        junction_caps(bad);
        from = std::min({from, bad, take_ramp_change()});
        return Remedy::again;
    }
    // An overlapped corner that failed goes back to one step before it is lowered.
    if (overlapped(bad)) {
        seg(bad).no_overlap = true;
        junction_caps(bad);
        from = std::min({from, bad, backward(bad + 1), take_ramp_change()});
        return Remedy::again;
    }
    // A block that ramped on from its start keeps the start's speed before its corner is
    // lowered (a start from rest used to keep one speed: random programs ran up to 1.2 % slower).
    if (seg(bad).ramped_on && !seg(bad).one_speed_start) {
        seg(bad).one_speed_start = true;
        from = std::min(from, bad);
        return Remedy::again;
    }
    // A leg whose falling kernel would start before its rising one (a dense junction's wide
    // stage right after a short block's start) is the dense class's, not the corner speed's: the
    // dense blocks beside it ramp on their own (sparse) at the corner's cap. (Lowered first, the
    // corner passed at 0.9x and the block after it then turned sparse all the same: firtp_cliffs
    // seed 2 program 151, a 1.47 mm block from rest in line with a 9.18 mm one, 0.1708 ->
    // 0.1817 s with the accelerations a quarter higher; now 0.1695 s.)
    if (order_failure_ && sparse_beside(bad, -infinity)) {
        from = std::min({from, bad, backward(std::min(bad + 2, count_ - 1)), take_ramp_change()});
        return Remedy::again;
    }
    // Lower the corner: the error grows about with the square of the speed.
    Segment& j = seg(bad);
    double factor = check_backoff;
    if (excess_ > 1.0) factor = std::clamp(0.999 / std::sqrt(excess_), 0.5, 0.999);
    const double lower = factor * std::max(j.b, j.next_a);
    r.lowered = bad, r.lowered_cap = j.learned_cap, r.lowered_for = limit_failure_;
    if (lower > 1e-6 * j.feed) {
        j.learned_cap = std::min(j.learned_cap, lower);
    } else {  // not even a crawl passes it: a stop (a corner at speed 0 would never start again)
        j.forced_stop = true;
        junction_caps(bad);
    }
    // A dense block keeps one speed: pinned to a junction this slow it would crawl. It ramps
    // on its own instead (sparse).
    sparse_beside(bad, j.learned_cap);
    from = std::min({from, bad, backward(bad), take_ramp_change()});
    return Remedy::again;
}

bool Lookahead::sparse_beside(std::size_t bad, double cap) {
    bool any = false;
    for (std::size_t k : {bad, bad + 1})
        if (k < count_ && seg(k).dense && !(k == 0 && frozen_.moving) && cap < 0.5 * sparse_estimate(k)) {
            seg(k).sparse_only = true;
            classify(k);
            if (k > 0) junction_caps(k - 1);
            if (k + 1 < count_) junction_caps(k);
            any = true;
        }
    return any;
}

void Lookahead::replan_end(std::size_t from) {
    // What bounded each junction the passes went over (for the report).
    for (std::size_t i = from; i + 1 < count_; ++i) {
        Segment& s = seg(i);
        s.bound_axis = -1;
        if (s.kind == Kind::stop) {
            s.bound = stop_bound(s);
            continue;
        }
        const double c = std::max(s.b, s.next_a);
        const double feed = std::min(target(i), target(i + 1));
        if (c >= feed * (1.0 - 1e-9)) s.bound = CornerBound::feed;
        else if (c >= s.learned_cap * (1.0 - 1e-9)) s.bound = CornerBound::checked;
        else if (s.kind == Kind::corner && c >= s.corner_cap * (1.0 - 1e-9)) s.bound = s.cap_bound;
        else if (s.kind == Kind::dense && c >= s.exit_max * (1.0 - 1e-9)) s.bound = CornerBound::room;
        else s.bound = CornerBound::lookahead;
        double most = 0.0;
        for (int a = 0; a < limits_.axes; ++a) {
            const double acc = limits_.axis[a].max_acceleration;
            if (acc > 0.0 && std::abs(s.turn.du[a]) / acc > most) most = std::abs(s.turn.du[a]) / acc, s.bound_axis = a;
        }
    }
    refresh_current_leg();
}

}  // namespace firtp
