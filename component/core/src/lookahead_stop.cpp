// Whether a corner between sparse blocks stops or blends (set_junction).
//
// Principle: the estimates (blend_loss, stop_loss) weigh what each choice loses against the
// speeds beside the corner. Where they say stop, it stops (stop_pays). Where they say blend, the
// two blocks beside the corner are planned as plan_segment would plan them (pair_time), once with
// the corner passed at its cap and once with a stop there, and the corner stops where that is
// more than a period faster. Blending keeps the tool moving, so a tie goes to it: the times are
// exact to the tick grid, a period.
//
// - The estimates misjudge short blocks the one way: a block's ramp into a corner in a slower
//   regime lowers its peak over its whole length, which a loss against that peak does not see.
//   firtp_cliffs seed 31 program 83 (0.13 and 0.34 mm, 62 degrees) stopped at 0.0015 mm and
//   blended at 0.0019 mm, 10 % slower; planned, it stops at both. Eight other estimates were
//   tried (docs/BENCHMARKS.md); none moved more plans the right way than the wrong one.
// - Where both blocks reach their feeds by the estimate's own peaks, the estimate stands: it was
//   measured within 0.6 ms of the samples there (blend_loss), and planning those corners as well
//   made firtp_worst_add's mean 10.7 us a block instead of 9.2.
// - The blocks' far ends are taken as they stand: block i entered as fast as the corner before
//   it allows (from rest after a stop), block i + 1 left as fast as the corner after it allows,
//   or stopped where it ends the window. The corner after is decided first (link()), so that is
//   its own cap, not an older one.
// - Where a plan does not fit (block i under way, or those speeds out of reach) the estimate
//   stands.
// - The searches stop at 0.05 % of the speed (about_highest). At a plan's 1e-13 (search.hpp)
//   firtp_worst_add's blocks cost 1.8 times as much.
#include <firtp/lookahead.hpp>
#include <firtp/search.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

using search::about_highest;

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();
}  // namespace

// A corner between sparse blocks takes its tolerance's regime (`tight`, its turn's box and cap
// there; `machine` likewise in the machine's) where that loses no more time by estimate
// (blend_loss; on a tie the faster corner, which a raised override may use). A faster corner
// alone does not pay: on a 90 degree corner between 30 mm blocks at 200 mm/s (0.002 mm) the
// tolerance's regime passed at 1.33 mm/s instead of 0.23 and took 0.652 s instead of 0.480, its
// ramps at 780 mm/s^2.
bool Lookahead::tight_pays(std::size_t i, const Regime& tight, double tight_alpha, double cap, const Regime& machine,
                           double machine_alpha, double machine_cap) const {
    return cap > machine_cap && blend_loss(i, tight, tight_alpha, cap) <= blend_loss(i, machine, machine_alpha, machine_cap);
}

// The peak block k's length allows between two ramps from v, boxes of alpha per unit of speed:
// (f^2 - v^2) alpha = its length (blend_loss).
double Lookahead::peak_estimate(std::size_t k, double v, double alpha) const { return std::sqrt(v * v + seg(k).length / alpha); }

// Passing corner i at v in `regime` (its turn's box turn_alpha), by estimate: the time lost against
// the speeds f beside it (each block's feed at the rate it runs, target(), or the peak its length
// allows; at the highest override's feeds a corner at 200 % was judged for speeds it never ran).
// Each ramp between f and v loses its kernel's width times (f - v) / 2 f; the ramps' kernels stay
// apart by the turn's reserves and jerk gaps (profile_legs), run at v. On the blocks' whole
// lengths: the decision does not change while the first one runs. (Measured on a 90 degree corner
// between 20 mm blocks at 100 mm/s, 0.05-0.5 mm: within 0.6 ms of the samples' cycle time.)
// A sparse regime's jerk gaps at its own stage, as spacing() finds them. (At the machine's, the
// widest A / J, a corner whose stage its blocks' feeds shorten needed none by estimate: a 123
// degree turn between a 0.46 mm block at 8.6 mm/s and a 2.4 mm one, in a 24 ms stage on a machine
// of 0.7 s, was estimated to lose 29.8 ms blended at 1.48 mm/s, 0.6 ms less than stopped, and lost
// 42 ms, 12 ms more: firtp_cliffs seed 1 program 243, +5.7 % with every tolerance a quarter
// larger, where as drawn the estimate stopped it.) A tolerance's regime (tight_pays) as before, at
// the machine's stage: without gaps there, as spacing() has none, it was taken where it ran slower
// (seed 3 program 60: 1.085 -> 1.106 s).
double Lookahead::blend_loss(std::size_t i, const Regime& regime, double turn_alpha, double v) const {
    const Segment& s = seg(i);
    const Segment& n = seg(i + 1);
    const double t2 = regime.t2, tb = v * turn_alpha, reserve = 0.5 * std::max(0.0, t2 - tb);
    double loss = 0.0, slowest = infinity;
    for (std::size_t k : {i, i + 1}) {
        const Segment* b = &seg(k);
        const double alpha = box(b->u, regime);
        const double f = std::min(target(k), peak_estimate(k, v, alpha));
        slowest = std::min(slowest, f);
        if (v < f) loss += ((f - v) * alpha + t2) * (f - v) / (2.0 * f);
    }
    const double gap_t2 = regime.sparse ? t2 : rules_.t2;
    const double before = rules_.needs_gap(-s.u, s.turn.direction, gap_t2) ? t2 : reserve;
    const double after = rules_.needs_gap(s.turn.direction, n.u, gap_t2) ? t2 : reserve;
    if (v < slowest) loss += (tb + before + after - t2) * (1.0 - v / slowest);
    return loss;
}

// Stopping at corner i instead, by the same estimate: the sized ramps beside it (sized_kernel)
// lose half their widths, and up to a period goes to the tick grid.
double Lookahead::stop_loss(std::size_t i) const {
    double loss = parameters_.period;
    for (std::size_t k : {i, i + 1}) {
        const Segment& b = seg(k);
        const double f = std::min(target(k), peak_estimate(k, 0.0, b.alpha));
        loss += 0.5 * sized_kernel(f, b.alpha, b.u_jerk).width();
    }
    return loss;
}

// By estimate, a corner between sparse blocks stops where passing it at v would lose more (a 30
// degree turn at 0.6 mm/s between 30 mm blocks at 200 mm/s keeps T2 / 2 more between its ramps
// than a stop and took 0.499 s against 0.474), or no less than a period less: the estimates are
// good to about a period, and a tie goes to the stop (TightCorner.*: a 135 degree turn at
// 0.02 mm blended in 0.285 s against the stop's 0.283). Short blocks too: held to a blend, a
// corner beside a 7.4 mm block passed at 0.2 mm/s where a stop took 40 ms less (firtp_cliffs
// seed 3 program 192, +16 % with the velocity limits a quarter higher: the block became short).
// Asked only between sparse blocks with sized stops (set_junction's `weigh`).
bool Lookahead::stop_pays(std::size_t i, double v) const {
    const Segment& s = seg(i);
    return stop_loss(i) < blend_loss(i, s.junction, s.turn_alpha, v) + parameters_.period;
}

// A stop at junction i (set_junction): nothing overlaps, no ramp shares the junction's stage.
void Lookahead::set_stop(std::size_t i, CornerBound why) {
    Segment& s = seg(i);
    s.kind = Kind::stop;
    s.overlap = 0.0;
    s.corner_cap = 0.0;
    s.cap_bound = why;
    s.junction = s.regime;
    s.turn_alpha = 0.0;
    s.out_ramp = seg(i + 1).in_ramp = Regime{-1.0};
}

// Corner i, set as a blend at its cap (the estimate did not stop it): a stop where the two blocks
// plan more than a period faster with one, unless both reach their feeds by estimate.
void Lookahead::stop_if_faster(std::size_t i) {
    Segment& s = seg(i);
    Segment& n = seg(i + 1);
    if (peak_estimate(i, s.corner_cap, box(s.u, s.junction)) >= target(i) &&
        peak_estimate(i + 1, s.corner_cap, box(n.u, s.junction)) >= target(i + 1))
        return;
    const double blended = pair_time(i);
    if (!std::isfinite(blended)) return;
    const Blend blend{s.kind, s.overlap, s.corner_cap, s.cap_bound, s.junction, s.turn_alpha, s.out_ramp, n.in_ramp};
    set_stop(i, CornerBound::stop_pays);
    const double stopped = pair_time(i);
    if (std::isfinite(stopped) && stopped < blended - parameters_.period) return;
    s.kind = blend.kind, s.overlap = blend.overlap, s.corner_cap = blend.corner_cap;
    s.cap_bound = blend.cap_bound, s.junction = blend.junction, s.turn_alpha = blend.turn_alpha;
    s.out_ramp = blend.out_ramp, n.in_ramp = blend.in_ramp;
}

// Block k's profile as plan_segment plans it, entered at a (a < 0: from rest, its start step the
// first ramp) and left at most at exit (a stop where exit_is_stop(k)): its legs' time, infinity
// where they do not fit; `entered` and `left` the speeds it takes.
double Lookahead::block_time(Fitting& f, std::size_t k, double a, double exit, double& entered, double& left) const {
    const double top = target(k);
    const bool stop = exit_is_stop(k);
    double p = 0.0, b = 0.0;
    if (a < 0.0) {
        p = stop ? about_highest([&](double x) { return f.probe(x, x, x); }, 0.0, top)
                 : about_highest([&](double x) { return f.probe(x, x, std::min(x, exit)); }, 0.0, top);
        a = p, b = stop ? p : std::min(p, exit);
    } else if (stop) {
        p = b = about_highest([&](double x) { return f.probe(a, x, x); }, a, std::max(a, top));
    } else {
        b = std::min(exit, about_highest([&](double x) { return f.probe(a, std::max(a, x), x); }, 0.0, std::max(a, exit)));
        p = about_highest([&](double x) { return f.probe(a, x, b); }, std::max(a, b), std::max({a, b, top}));
    }
    entered = a, left = b;
    const ProfileLegs legs = profile_legs(rules_, f.input(a, b), a, p, b);
    return legs.fits ? legs.duration() : infinity;
}

// Block i entered as fast as the corner before it allows; after a stop from rest (-1).
double Lookahead::pair_entry(std::size_t i) const {
    return entry_is_stop(i) ? -1.0 : std::min({seg(i - 1).corner_cap, target(i - 1), target(i)});
}

// Blocks i and i + 1 from the first's entry step to the second's exit step (command time), with
// junction i as set: passed at its cap, no faster than block i + 1 may leave at, or a stop, the
// two at rest between its steps (link_next_a's `rest`). infinity where a plan does not fit.
double Lookahead::pair_time(std::size_t i, double* left) const {
    if (i == 0 && frozen_.moving) return infinity;  // (block 0 under way: its entry is frozen)
    const double entry = pair_entry(i);
    const double exit = exit_is_stop(i + 1) ? 0.0 : std::min({seg(i + 1).corner_cap, target(i + 1), target(i + 2)});
    Fitting first(*this, i), second(*this, i + 1);
    double a0 = 0.0, b0 = 0.0, a1 = 0.0, b1 = 0.0;
    if (seg(i).kind == Kind::stop) {
        const double t = block_time(first, i, entry, 0.0, a0, b0) + block_time(second, i + 1, -1.0, exit, a1, b1);
        if (left) *left = b1;
        return t + rules_.spacing(exit_shape(i, b0), entry_shape(i + 1, a1));
    }
    const double v = about_highest(
        [&](double x) {
            const double y = exit_is_stop(i + 1) ? x : std::min(x, exit);
            return second.probe(x, std::max(x, y), y);
        },
        0.0, std::min({seg(i).corner_cap, target(i), target(i + 1)}));
    const double t = block_time(first, i, entry, v, a0, b0);
    const double u = block_time(second, i + 1, b0, exit, a1, b1);
    if (left) *left = b1;
    return t + u;
}

// The newest block i + 1, classed dense after sparse block i by the estimates, ends at the
// window's stop: held at one speed, it crawls to its stop at the corner's speed, where sparse it
// ramps from a slower corner or a stop (firtp_cliffs seed 7 program 108, a last 0.36 mm block:
// dense at 4.8 mm/s with every tolerance a quarter larger, 8.5 % slower than sparse after a stop).
// Both planned, from block i's entry to the stop's end (half its step's width): sparse where that is
// more than a period faster. The next block decides its class again as the estimates left it
// (link(): otherwise the stop the sparse plan took kept it sparse for good, stop_pays, and a dense
// run after it stopped there: seed 5 program 295, 1.086 -> 1.169 s).
void Lookahead::class_if_faster(std::size_t i) {
    Segment& s = seg(i);
    Segment& n = seg(i + 1);
    if (i + 2 != count_ || !n.dense || s.dense || s.kind != Kind::corner || (i == 0 && frozen_.moving)) return;
    const double entry = pair_entry(i);
    const double exit = std::min({corner_exit_cap(i), target(i), target(i + 1), room_cap(i + 1, n.alpha)});
    auto width = [](const StepShape& shape) { return 0.5 * (shape.box + shape.t2); };  // (centred on its time)
    Fitting first(*this, i);
    double a0 = 0.0, b0 = 0.0;
    const double ahead = block_time(first, i, entry, exit, a0, b0);
    const double dense = b0 > 0.0 ? ahead + seg_length(i + 1) / b0 + width(exit_shape(i + 1, b0)) : infinity;
    const Regime regime = n.regime;
    const bool narrowed = n.narrowed;
    n.dense = n.narrowed = false;
    set_regime(n, n.own);
    junction_caps(i);
    double left = 0.0;
    const double sparse = pair_time(i, &left) + width(exit_shape(i + 1, left));
    if (sparse < dense - parameters_.period) return void(n.sparse_as_newest = true);
    n.dense = true, n.narrowed = narrowed;
    set_regime(n, regime);
    junction_caps(i);
}

}  // namespace firtp
