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
//
// The stop at the window's end then lies beyond anything the motion commits to before more blocks
// join, so the motion is that of the whole queue planned, but where a check lowered a corner for a
// path that ended elsewhere (tests/core/reach_test.cpp).
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
// A batch's plan waits for the next period where the blocks before what it changes are this many
// (the next step's, and the one after it, may freeze then); a batch waits at most this many commits
// for a period in which nothing freezes (then it is planned whole, as it is where little is under way).
constexpr std::size_t split_from = 4;
constexpr std::uint32_t join_waits_most = 8;

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
    return true;
}

void Lookahead::defer_beyond(std::size_t keep) {
    if (keep == 0 || keep >= count_) return;
    keep_ = keep;
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
}

void Lookahead::rejoin_some() {
    if (deferred_ == 0 || join_.open || join_.done == timeline_->now()) return;
    if (++rejoin_clock_ % horizon_every == 0 || count_ == 0) {
        const std::size_t h = horizon();
        keep_ = h < count_ ? h : count_ + horizon_growth;
    }
    if (count_ >= keep_) return;
    const std::size_t before = count_;
    // (Held, or a change to try again: one at a time, as the hold's stop and the change's snapshot
    // expect.)
    const bool batch = !held_ && !retry_ && before <= batch_window_most;
    const std::size_t n = std::min(deferred_, batch ? std::clamp(tail_ + 1, std::size_t{1}, rejoin_batch) : std::size_t{1});
    // A batch's plan comes in the next period if nothing freezes in this one; it waits a few
    // commits for such a period.
    const bool under_way = n > 1 && frozen_.moving, split = under_way && !next_due();
    if (under_way && !split && ++join_.waited <= join_waits_most) return;
    join_.waited = 0;
    if (n > 1) {
        for (std::size_t i = 0; i < before; ++i) snapshot_[i] = seg(i);
        undo_ = plan_scalars();
    }
    for (std::size_t k = 0; k < n; ++k) take_waiting(), link_newest();
    // The bounds now, one plan for them all (as plan_batch) now or at the next commit: where what
    // changed lies past the steps the next period may freeze.
    join_.open = true;
    join_.before = before, join_.undoable = n > 1;
    join_.lowest = bounds_joined(before);
    if (!split || join_.lowest < split_from) plan_join();
}

void Lookahead::plan_join() {
    join_.open = false;
    join_.done = timeline_->now();
    const std::size_t before = join_.before, lowest = join_.lowest;
    const bool planned = replan_joined(before, lowest, join_.undoable);
    tail_ = before > lowest ? before - lowest : 1;
    if (planned) return;
    // No plan short of the last resort, which is one block's: the window as they found it, and the
    // first of them alone.
    for (std::size_t i = 0; i < before; ++i) seg(i) = snapshot_[i];
    deferred_ += count_ - before;
    stats_.rejoined -= count_ - before;
    count_ = before;
    restore(undo_);
    ++stats_.batches_undone;
    take_waiting();
    join(Planning::now);
}

}  // namespace firtp
