// The window's reach. Only the blocks the motion can reach soon need a plan now: four times the way
// a stop from the fastest of them takes (v (v alpha + T2) / 2, in each block's own regime), and
// at least min_window blocks. The others wait in the ring after the window (deferred_) and join it
// as the motion uses it up, in batches under one plan.
//
// - A change of rate plans the blocks within reach again and leaves the rest waiting: planning the
//   whole window cost 10 ms with 4096 blocks queued (32 ms at worst: firtp_worst_override).
// - A block added (Planning::now) to a window that already reaches that far waits too. Each block
//   planned on its own re-planned and re-checked the stop at the end of the known path, which
//   on a dense path spans dozens of blocks (0.35 mm chords at jerk 1e5: 130 us an add). A batch
//   pays for that stop once.
// - Under way, a batch's join is spread over the periods after it, one step a commit: the bounds
//   16 junctions at a time, the forward pass, the check's legs and limits, its corners 16 at a
//   time (Lookahead::Join). At jerk 1e5 a join of 16 chords re-plans the 35-50 blocks braking to
//   the window's end: 85-115 us in each of two periods before, at most 44 us a period now
//   (firtp_worst_period). Steps freeze meanwhile, far before the join's blocks; where what it
//   changes comes within join_split_from segments of the front, or a start is due, the rest is
//   done at once. The passes and the check are the same on the same blocks: so is the plan.
//
// The stop at the window's end then lies beyond anything the motion commits to before more blocks
// join, so the motion is that of the whole queue planned, but where a check lowered a corner for a
// path that ended elsewhere (tests/core/reach_test.cpp).
//
// - A window still filling under way (LinuxCNC hands firtp_tp one block a servo period; on 0.35 mm
//   chords at 300 mm/s the motion uses them about as fast, so the window never reaches that far)
//   gathers its blocks the same way: from min_window blocks on, a block added under way waits, and
//   the waiting ones join as one batch, spread over periods, once there are as many as a join's
//   bounds change blocks back or they have waited gather_periods. Steps freeze meanwhile, against
//   the stop at the end of the blocks joined so far: a checked plan, as one with fewer blocks
//   known. Joining them at once wherever the front's bounds came from that stop (front_final)
//   did so before nearly every freeze and cost 130-170 us a period at jerk 1e5: on the chords
//   and the random programs of tests/core/arrival_test.cpp the motion is the same without it.
//   firtp_worst_period --per-period 1 --with-adds --feed 300 --laps 2: periods over 50 us under
//   way 347 -> 171 -> 6, planning 43.2 -> 26.2 -> 12.4 ms (docs/BENCHMARKS.md).
#include <firtp/lookahead.hpp>

#include <algorithm>
#include <limits>

namespace firtp {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::size_t min_window = 32;
// Waiting blocks join while the window holds fewer than it must keep, one more at a time than the
// last join re-planned blocks before them (its bounds changed that far back), up to rejoin_batch:
// a batch then costs about two joins of one, and a block on a dense path a fraction of one (on
// random corners, whose bounds change a block back, pairs: 8.4 -> 8.1 us a block). Every
// horizon_every commits (or adds) the reach is measured again; where faster blocks need more, it
// grows by horizon_growth blocks.
constexpr std::size_t rejoin_batch = 16;
constexpr std::uint32_t horizon_every = 16;
constexpr std::size_t horizon_growth = 8;
// A batch that no plan passes is undone from a copy of the window: beyond this many blocks, one
// joins at a time (the copy would cost more than the plans it saves).
constexpr std::size_t batch_window_most = 512;
// Under way, a batch's join takes one step a commit (Lookahead::Join): so many junctions' bounds,
// or corners measured, a step.
constexpr std::size_t bounds_a_step = 16;
constexpr std::size_t corners_a_step = 16;
// A window still filling: from gather_from blocks on (from 4, seed 2 program 100 of
// tests/core/arrival_test.cpp fed two a period ran 6e-6 mm off the whole program's samples), a
// block waits at most gather_periods for others to join with.
constexpr std::size_t gather_from = min_window;
constexpr std::int64_t gather_periods = 8;

}  // namespace

std::size_t Lookahead::horizon() const {
    double length = 0.0, need = 0.0;
    for (std::size_t i = 0; i < count_; ++i) {
        if (i >= min_window && length > need) return i;
        const Segment& s = seg(i);
        // A dense block's speed as its bounds allow; braking for a hold, as its junctions would.
        double v = s.feed_max;
        if (s.dense) v = std::min(v, std::max({s.entry_max, s.exit_max, s.brake ? dense_estimate(i) : 0.0}));
        need = std::max(need, 2.0 * v * (v * s.alpha + s.regime.t2));
        length += seg_length(i);
    }
    return count_;
}

bool Lookahead::waits_beyond() {
    if (count_ < min_window + rejoin_batch || ++add_clock_ % horizon_every != 0) return false;
    const std::size_t h = horizon();
    if (h + rejoin_batch > count_) return false;
    keep_ = h;
    filling_ = false;
    return true;
}

void Lookahead::defer_beyond(std::size_t keep) {
    if (keep == 0 || keep >= count_) return;
    keep_ = keep;
    filling_ = false;
    deferred_ += count_ - keep;
    count_ = keep;
    // The last block kept ends the known path, as it did when it came (add): a stop after it.
    Segment& last = seg(count_ - 1);
    last.turn = Turn{};
    last.turn_box = -1.0;
    last.kind = Kind::stop;
    last.junction = last.regime;
    last.out_ramp = Regime{-1.0};
    last.sparse_cap = last.tight_cap = last.corner_cap = 0.0;
    last.learned_cap = infinity;
    if (count_ >= 2) link(count_ - 2);
    else classify(0);
    backward(count_ - 1);
}

void Lookahead::take_waiting() {
    // As add() made it: what its block gave, nothing a plan or a check added since.
    Segment& s = seg(count_);
    Segment fresh;
    fresh.start = s.start, fresh.end = s.end, fresh.u = s.u, fresh.length = s.length;
    fresh.feed = s.feed, fresh.feed_max = s.feed_max, fresh.tolerance = s.tolerance;
    fresh.exact_stop = s.exact_stop, fresh.dwell = s.dwell, fresh.added = s.added;
    fresh.type = s.type, fresh.line = s.line;
    arrive(fresh);
    s = fresh;
    --deferred_;
    ++stats_.rejoined;
    if (filling_) ++stats_.gathered;
}

void Lookahead::rejoin_some() {
    if (deferred_ == 0 || join_.open || join_.done == timeline_->now()) return;
    if (++rejoin_clock_ % horizon_every == 0 || count_ == 0) {
        const std::size_t h = horizon();
        keep_ = h < count_ ? h : count_ + horizon_growth;
        filling_ = filling_ && h >= count_;
    }
    if (count_ >= keep_ && !filling_) return;
    if (gathers()) return;
    join_waiting(rejoin_count());
}

std::size_t Lookahead::batch_size() const { return std::clamp(tail_ + 1, std::size_t{1}, rejoin_batch); }

std::size_t Lookahead::rejoin_count() const {
    // (Held, or a change to try again: one at a time, as the hold's stop and the change's snapshot
    // expect.)
    const bool batch = !held_ && !retry_ && count_ <= batch_window_most;
    return std::min(deferred_, batch ? batch_size() : std::size_t{1});
}

void Lookahead::join_waiting(std::size_t n) {
    const std::size_t before = count_;
    if (n > 1) {
        for (std::size_t i = 0; i < before; ++i) snapshot_[i] = seg(i);
        undo_ = plan_scalars();
    }
    for (std::size_t k = 0; k < n; ++k) take_waiting(), link_newest();
    // The bounds from the new end (the junctions before before - 2 were settled), then one plan
    // for them all from there or the junction they joined on, whichever is first (as plan_batch).
    const std::int64_t done = join_.done;
    join_ = Join{};
    join_.open = true, join_.undoable = n > 1, join_.done = done;
    join_.before = before;
    join_.bounds = bounds_joined(before);
    join_step(!(n > 1 && frozen_.moving));  // a batch under way spreads over periods
}

bool Lookahead::fills_under_way() const {
    return frozen_.moving && !held_ && !retry_ && count_ >= gather_from && count_ <= batch_window_most;
}

bool Lookahead::gathers() const {
    if (!filling_ || finished_ || !fills_under_way()) return false;
    const double waited = static_cast<double>(timeline_->now()) * parameters_.period - seg(count_).added;
    return deferred_ < batch_size() && waited < static_cast<double>(gather_periods) * parameters_.period;
}

std::size_t Lookahead::join_front() const {
    const Join& j = join_;
    const std::size_t joined = j.before > 0 ? j.before - 1 : 0;
    switch (j.stage) {
        case Join::Stage::bounds: return std::min(j.bounds.next > 0 ? j.bounds.next - 1 : 0, joined);
        case Join::Stage::plan: return std::min(j.lowest, joined);
        case Join::Stage::check: return j.plan.from;
        case Join::Stage::corners: return std::min(j.plan.from, j.check.from - j.check.shift);
    }
    return 0;
}

void Lookahead::join_popped() {
    Join& j = join_;
    auto down = [](std::size_t& i) { i = i > 0 ? i - 1 : 0; };
    ++j.pops;
    down(j.before), down(j.lowest);
    down(j.bounds.next), down(j.bounds.last), down(j.bounds.settled), down(j.bounds.changed);
    down(j.plan.from), down(j.plan.changed), down(j.plan.kept), down(j.plan.lowered);
    ++j.check.shift;
}

void Lookahead::join_step(bool whole) {
    Join& j = join_;
    whole = whole || join_front() < join_split_from;
    std::size_t bad = count_;
    Checked checked = Checked::corners;
    switch (j.stage) {
        case Join::Stage::bounds:
            if (!backward_some(j.bounds, whole ? static_cast<std::size_t>(-1) : bounds_a_step)) return;
            settle_end_flags();
            j.lowest = j.bounds.changed;
            j.stage = Join::Stage::plan;
            if (!whole) return;
            [[fallthrough]];
        case Join::Stage::plan:
            if (!replan_begin(joined_first(j.before, j.lowest), j.plan)) return join_planned(true);
            replan_forward(j.plan);
            j.stage = Join::Stage::check;
            if (!whole) return;
            [[fallthrough]];
        case Join::Stage::check:
            checked = check_begin(j.plan.from, j.plan.changed, &bad, j.check);
            j.stage = Join::Stage::corners;
            if (checked == Checked::corners && !whole) return;
            [[fallthrough]];
        case Join::Stage::corners:
            if (checked == Checked::corners)
                checked = check_corners(j.check, whole ? static_cast<std::size_t>(-1) : corners_a_step, &bad);
            break;
    }
    if (checked == Checked::corners) return;
#ifdef FIRTP_FORCE_UNDO
    // Test builds only (tests/core: core_forced_undo_tests): every spread join that passed while
    // steps froze is undone as if no plan had passed, so the randomized suites run the rare undo.
    if (checked == Checked::passed && j.undoable && j.froze) return join_planned(false);
#endif
    if (checked == Checked::passed) {
        replan_passed(j.plan);
        replan_end(j.plan.from);
        return join_planned(true);
    }
    switch (replan_failed(j.plan, bad, j.undoable)) {
        case Remedy::undo: return join_planned(false);
        case Remedy::kept: return join_planned(true);
        case Remedy::planned: replan_end(j.plan.from); return join_planned(true);
        case Remedy::again: ++j.plan.attempt; return join_planned(replan_run(j.plan, j.undoable));
    }
}

void Lookahead::join_planned(bool planned) {
    join_.open = false;
    join_.done = timeline_->now();
    const std::size_t before = join_.before, lowest = join_.lowest;
    tail_ = before > lowest ? before - lowest : 1;
    if (planned) return;
    // No plan short of the last resort, which is one block's: the window as they found it (less
    // what froze since: commit() keeps the front's copy), and the first of them alone.
    for (std::size_t i = 0; i < before; ++i) seg(i) = snapshot_[i + join_.pops];
    deferred_ += count_ - before;
    stats_.rejoined -= count_ - before;
    if (filling_) stats_.gathered -= std::min<std::uint64_t>(stats_.gathered, count_ - before);
    count_ = before;
    PlanScalars undo = undo_;
    if (undo.ramp_change != static_cast<std::size_t>(-1)) undo.ramp_change = undo.ramp_change > join_.pops ? undo.ramp_change - join_.pops : 0;
    if (join_.froze) undo.max_width = std::max(undo.max_width, max_width_);  // (the frozen steps' kernels)
    restore(undo);
    ++stats_.batches_undone;
    take_waiting();
    join(Planning::now);
}

}  // namespace firtp
