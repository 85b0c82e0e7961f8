// Changes of rate under way: feed override, hold and resume. A change plans the blocks near the
// motion again at once and lets the rest wait beyond the window (lookahead_reach.cpp), so a change
// costs the same with 64 blocks waiting as with 4096.
#include <firtp/lookahead.hpp>

#include <algorithm>
#include <limits>

namespace firtp {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double hold_crawl = 1e-3;  // of the speed before it: a hold's junction this slow is its stop

}  // namespace

// ---- Rate --------------------------------------------------------------------------------------

void Lookahead::set_rate(double rate) {
    rate = std::clamp(rate, 0.0, max_rate_);
    const bool hold = rate == 0.0;
    const bool same = hold == held_ && (hold || rate == rate_);
    if (same) {  // (a join under way goes on at the next commit)
        if (batch_.open) plan_batch();
        return;
    }
    plan_added();
    if (!hold) rate_ = rate;
    // A resume whose plan has not passed yet (retried at each tick) left the hold's braking in the
    // accepted plan: a new rate before it passes resumes too (seed 56, program 634: braked to rest
    // and never started again).
    const bool resumed = !hold && (held_ || hold_remnants());
    held_ = hold;
    retry_ = false;
    if (count_ > 0) replan_from_front(resumed);
}

void Lookahead::replan_from_front(bool resuming) {
    // The accepted plan is kept should no plan at the new rate pass the check (it goes on, and the
    // change is tried again at the next tick): the block under way may not be re-planned unchecked.
    const std::size_t keep = horizon();
    take_snapshot(keep);
    defer_beyond(keep);
    if (resuming) unsplit();  // the hold's stop goes
    replan(0);
}

// ---- Hold --------------------------------------------------------------------------------------

// Both move the segments before i, not those after: the blocks left out of the window stay
// where they are in the ring.
void Lookahead::insert_after(std::size_t i, const Segment& s) {
    head_ = head_ > 0 ? head_ - 1 : segments_.size() - 1;
    for (std::size_t k = 0; k <= i; ++k) seg(k) = seg(k + 1);
    seg(i + 1) = s;
    ++count_;
}

void Lookahead::erase(std::size_t i) {
    for (std::size_t k = i; k > 0; --k) seg(k) = seg(k - 1);
    head_ = ring(1);
    --count_;
}

bool Lookahead::hold_remnants() const {
    for (std::size_t i = 0; i < count_; ++i)
        if (seg(i).brake || seg(i).hold_split || seg(i).hold_end) return true;
    return false;
}

std::size_t Lookahead::hold_stop_index() const {
    // A hold's split and a block braking to rest are stops too (classify), so the first stop ahead
    // is the hold's if the hold brakes into it.
    for (std::size_t i = 0; i < count_; ++i)
        if (exit_is_stop(i)) return seg(i).brake ? i : count_;
    return count_;
}

void Lookahead::place_hold_stop() {
    for (std::size_t i = 0; i < count_; ++i) seg(i).brake = false;
    if (!frozen_.moving) return;  // at rest: the hold keeps it there
    double a = frozen_.speed;
    for (std::size_t i = 0; i < count_; ++i) {
        Segment& s = seg(i);
        // The earliest stop in this segment from speed a: one leg, then the stop step.
        ProfileInput in = profile_input(i, a, a);
        in.out = {a * s.alpha, -s.u, s.regime.t2};
        in.out_reserve = 0.0;
        in.out_alpha = 0.0, in.out_t2 = -1.0;  // a split's stop shares no corner's regime (set_junction)
        in.length = 0.0;
        const double reach = a * profile_legs(rules_, in, a, a, a).x0;
        const double start = i == 0 ? frozen_.consumed : seg(i - 1).overlap_at(a);  // where its legs begin
        // Also where the block ends in a stop: that stop may lie far beyond the earliest one.
        if (reach < legs_length(i, a, s.b) * (1.0 - 1e-9) && depth() < segments_.size()) {
            Segment rest = s;  // the rest of the block, from the stop on, with the junction after it
            const double at = start + reach;
            const AxisVector point = s.start + s.u * at;
            rest.start = point;
            rest.length = s.length - at;
            rest.dwell = 0.0;  // the block's dwell came before it
            s.end = point;
            s.length = at;
            s.hold_split = true;
            s.exact_stop = false;
            s.brake = true;
            set_turn(s, s.u);
            s.learned_cap = infinity;
            insert_after(i, rest);
            junction_caps(i);
            backward(i + 1);
            return;
        }
        s.brake = true;
        plan_segment(i, i == 0 ? a : entry_for(i));
        if (exit_is_stop(i)) return;  // an exact stop comes first: the hold stops there
        // It brakes to rest at its end, or to a crawl there (hold_crawl, as a dense junction below):
        // the hold stops there.
        if (!(s.b > hold_crawl * std::max({s.a, s.p, a}))) {
            s.hold_end = true;
            junction_caps(i);
            backward(i);
            return;
        }
        if (i + 1 < count_) seg(i + 1).brake = true;
        a = s.kind == Kind::corner ? s.b : entry_for(i + 1);
        // A dense junction that brakes to almost nothing is the hold's stop: the next block would
        // otherwise be entered at a crawl, which a dense block keeps (seed 35, program 350).
        if (s.kind == Kind::dense && a < hold_crawl * s.b) {
            seg(i + 1).brake = false;
            s.hold_end = true;
            junction_caps(i);
            backward(i);
            return;
        }
        if (!(a > 0.0)) return;
    }
}

void Lookahead::take_snapshot(std::size_t keep) {
    snapshot_count_ = std::min(count_, keep);
    snapshot_cut_ = count_ - snapshot_count_;
    snapshot_head_ = head_;
    for (std::size_t i = 0; i < snapshot_count_; ++i) snapshot_[i] = seg(i);
    snapshot_taken_ = true;
}

void Lookahead::unsplit() {
    for (std::size_t i = 0; i < count_; ++i) {
        Segment& s = seg(i);
        s.brake = false;
        if (!s.hold_end) continue;
        s.hold_end = false;
        if (i + 1 < count_) junction_caps(i);
        backward(i);  // (from the end, the pass found nothing changed there and stopped before it)
    }
    for (std::size_t i = 0; i + 1 < count_; ++i) {
        Segment& s = seg(i);
        if (!s.hold_split) continue;
        const Segment& rest = seg(i + 1);
        const double length = s.length + rest.length;
        const AxisVector start = s.start;
        const double dwell = s.dwell;
        const Regime in_ramp = s.in_ramp;  // its entry's (the block before may be gone)
        s = rest;
        s.start = start;
        s.dwell = dwell;
        s.in_ramp = in_ramp;
        s.length = length;
        erase(i + 1);
        if (i + 1 < count_) link(i);
        else classify(i);
        // The bounds before it still brake for the hold's stop: from here down (from the end, the
        // pass found nothing changed there and stopped; a resume kept braking for 35 blocks).
        backward(i);
        plan_segment(i, i == 0 && frozen_.moving ? frozen_.speed : entry_for(i));  // its legs cover it whole
        return;
    }
}

}  // namespace firtp
