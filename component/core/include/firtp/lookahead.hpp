// The limit-driven planner: blocks wait in a look-ahead window until their motion is settled, then
// become legs on the timeline just before their kernels start.
//
// Each block gets an entry, a cruise and an exit speed (profile.hpp); where blocks meet, the step
// between the two speeds is the corner (junction.hpp). The speeds come from two passes, as in any
// look-ahead planner:
//   backward: from a stop at the end of the known path, the highest speed each block may enter
//             and leave with and still stop in time (at the highest feed override);
//   forward:  from the motion already under way, the speeds actually planned, at the feed the
//             override asks for.
// Junction kinds: a stop (exact stop, reversal, end of the path), a corner at one speed on both
// sides (where a block is long enough for ramps of its own), or, between two short blocks (dense
// paths: chords, CAM output), a step that changes speed and direction at once. A block between two
// stops is never dense: its sized start and stop make the jerk-limited rest-to-rest move.
//
// What the passes guarantee by construction: the spacing rules of profile.hpp at every step, so
// velocity, acceleration and jerk stay within the limits. What they estimate: the corner error
// where neighbouring steps overlap a corner. So every change is checked before it is accepted:
// the limits by the exact sweep and the corner errors by the closest approach (motion_check.hpp);
// where a corner fails, its speed is lowered and the passes run again. The plan that was accepted
// last is always a checked plan that stops at the end of the known path, so whatever has started
// can always be brought to rest.
//
// A block's speeds are final once blocks after it can no longer change them (the backward bound
// at its exit is its own, not the end's, and its junction settled: the block after next is known;
// a run of dense blocks, whose one speed a block a slow junction further on can lower more than a
// stop at the end does, has a known end): its steps start only then, or when the window is full,
// or when the motion would otherwise have to start late. So the motion does not depend on when
// blocks arrive, only on which, but where a later check refuses what the start has already
// committed to, or the block under way is planned again at another moment
// (tests/core/arrival_test.cpp: seeds 1-20 alike wherever no check lowered a corner).
//
// Only the blocks the motion can reach soon are planned: a change of rate (override, hold, resume)
// plans those again, and the others, with blocks added to a window that already reaches that far,
// wait beyond it and join it in batches as the motion uses it up (lookahead_reach.cpp). Neither a
// change's cost nor an add's grows with the queue or with the stop at the end of the path. Blocks
// that come under way to a window still short of that reach (one a period, as LinuxCNC sends
// them) wait and join in batches too.
#pragma once

#include <firtp/junction.hpp>
#include <firtp/kernel.hpp>
#include <firtp/motion_check.hpp>
#include <firtp/parameters.hpp>
#include <firtp/profile.hpp>
#include <firtp/report.hpp>
#include <firtp/search.hpp>
#include <firtp/timeline.hpp>
#include <firtp/types.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace firtp {

class Lookahead {
public:
    Lookahead(const PlannerParameters& parameters, Timeline& timeline, const AxisVector& start);

    // Validated by the caller; queue_full leaves everything as it was; skipped: zero length.
    // Planning::at_update: the speeds and their check wait for the next commit or rate change.
    Result add(const Block& block, Planning when = Planning::now);
    // No more blocks follow for now: the stop at the end is the end of the program.
    void finish() {
        if (!finished_) finish_join();  // (the end a join's bounds found moves)
        finished_ = true;
    }
    // Freeze every step whose kernel starts by the timeline's current tick: its leg goes to the
    // timeline. Before tick().
    void commit();
    // Feed override: the rate for the blocks not under way yet; 0 = hold: stop as soon as the
    // limits allow, on the path; a rate again resumes (where the stop has not begun, the block
    // goes on as if there had been none).
    void set_rate(double rate);
    double rate() const { return held_ ? 0.0 : rate_; }
    // Everything planned is dropped; rest at `position`.
    void reset(const AxisVector& position);

    // A start (from rest, or after a stop) is due at the next commit: it then asks whether the
    // window settles it (final_for_start), so a caller adding blocks in batches fills it first.
    bool start_due() const;
    bool empty() const { return depth() == 0; }  // nothing waits
    bool at_rest() const { return !moving(); }  // nothing under way (blocks may wait)
    std::size_t depth() const { return count_ + deferred_; }
    std::size_t free() const { return depth() < capacity_ ? capacity_ - depth() : 0; }
    const AxisVector& goal() const { return goal_; }
    const PlannerStats& stats() const { return stats_; }
    // The next corner report, once its junction's motion is final (false: none).
    bool take_report(CornerReport& report);
    double max_kernel_width() const { return max_width_; }

private:
    // Of a corner's epsilon: the exact check accepts errors up to (1 - check_margin) epsilon (what
    // the samples round to may differ a little); corners are planned to (1 - plan_margin) epsilon,
    // inside that by enough that the check's bound on the chords (closest_approach: the path's
    // error plus the sag its acceleration allows) passes them without measuring every chord.
    static constexpr double check_margin = 1e-6, plan_margin = 2e-6;
    // run_epsilon: a dense run longer than this many blocks keeps the whole tolerance.
    static constexpr std::size_t run_walk = 8;
    // dense_estimate: a block this many times as long as its dense neighbour next to a stop is
    // held to the speed that neighbour's leg leaves its junction step.
    static constexpr double dense_neighbour_ratio = 20.0;
    enum class Kind : std::uint8_t { stop, corner, dense };

    // How a step is smoothed: the jerk stage T2 and, per axis, the acceleration its box may
    // reach. Sparse steps use A and T2 = max A / J over the axes moving along them (a block's own
    // along it, a corner's along either block; every other axis' box held to J T2), so a slow-jerk
    // axis that does not move leaves them alone (sparse_regime); a block's own steps in no longer
    // a stage than their acceleration along it needs, and no stage longer than its feed's (every
    // box within J T2: own_regime, corner_regime, feed_stage). The ramps beside a sparse corner
    // take the corner's stage where it is longer (sparse_ramp), so they share its moving
    // average. A dense run (dense.hpp) uses T2_d = 2 h / J with h = min(A, cbrt(3 eps J^2)) (eps:
    // run_epsilon's: no more than a short run next to a stop is long), the largest over the axes
    // moving in it (the others' boxes held to J T2_d / 2): the run's accelerations may then swing
    // from -h to +h within T2_d, and smoothing a curve at acceleration h by T2_d moves it by
    // h T2_d^2 / 24 <= eps / 2. A sparse block's ramps next to a corner in a run's regime share it
    // (Segment::in_ramp; not a narrowed run's shorter one), and so do a corner's between sparse
    // blocks where it takes its tolerance's regime (tight_pays); a sparse block's start and stop
    // are sized to themselves (sized()).
    struct Regime {
        double t2 = 0.0;
        AxisVector cap = AxisVector::Zero();
        bool sparse = false;  // a sparse regime: the acceleration limits, T2 at most max A / J of `axes`
        unsigned axes = ~0u;  // a sparse regime's axes (bit a: axis a; all: sparse_)
        bool operator==(const Regime&) const = default;
    };

    struct Segment {
        AxisVector start, end, u;
        double length = 0.0;
        double feed = 0.0;       // at 100 %, capped by the axis velocity limits along u
        double feed_max = 0.0;   // at the highest override
        double alpha = 0.0;      // T1 per unit of speed change along u (in its regime)
        double u_box = -1.0;     // rules_.unit_box(u): the spacing rules' jerk gaps (any regime)
        double u_jerk = 0.0;     // max_a |u_a| / J_a: a sized step's T1 T2 per unit of speed (sized_kernel)
        bool short_block = false;  // shorter than a ramp to its feed and back
        bool dense = false;      // short between smooth junctions: one speed, changed at the junctions
        bool narrowed = false;   // dense, its regime below dense_epsilon's (run_epsilon)
        bool sparse_as_newest = false;  // the estimates class it dense; as the newest, planned faster sparse (class_if_faster)
        bool sparse_only = false;  // a junction of it failed its check far below the block's own pace
        bool ramped_on = false;    // planned from its start (from rest or just started) to a plateau above it
        bool one_speed_start = false;  // that ramp on failed the check at its exit: it keeps its start's speed
        Regime regime;           // of its own steps (start, stop, ramps)
        Regime own;              // own_regime(): its regime where sparse (found on arrival)
        double feed_t2 = 0.0;    // feed_stage()
        // A corner in a dense run's regime (a dense neighbour) shares its jerk stage with the
        // ramps beside it on this block: the ramp after the entry (in_ramp) and the one before
        // the exit (out_ramp) are smoothed in the corner's regime, their boxes up to J T2, and
        // overlap the corner's kernel instead of waiting for it (arcs.ngc). t2 < 0: `regime`.
        Regime in_ramp{-1.0}, out_ramp{-1.0};
        bool ramps_capped = true;  // its shared ramps reach J T2; false once a check found a jerk there
        bool exact_stop = false;
        bool forced_stop = false;  // no checked plan passed it: the tool stops there
        bool hold_split = false;   // it ends where a hold stops the tool (the rest of the block follows)
        bool hold_end = false;     // a hold stops the tool at its end (no split needed)
        bool brake = false;        // a hold is braking through it: its speeds as low as they go
        double tolerance = 0.0;
        // G4 before it: at rest this long after the previous stop has settled (or, from rest,
        // after `added`, the timeline clock (s) when it came).
        double dwell = 0.0;
        double added = 0.0;
        MotionType type = MotionType::feed;
        std::int64_t line = 0;
        // The junction after it (valid once the next segment exists; the last one ends in a stop).
        Turn turn;
        double turn_box = -1.0;    // rules_.unit_box(turn.direction)
        // The paper's overlap (Sec. 3) at a corner turning by 120 degrees or more, |u + u'| <= 1: the
        // next block's pulse rises Tk before this one's falls, so the junction is two steps with a
        // leg at V (u + u') between them, never faster than V, and the corner takes Tk less. Each
        // block gives up min(overlap, V overlap_tk) to that leg, Tk = that / V: at most overlap (the
        // tolerance's, set_overlap), and at most overlap_tk long (a hold must wait for the second
        // step once the first has started). 0: one step.
        double overlap = 0.0;
        double overlap_tk = 0.0;
        bool no_overlap = false;   // the check refused it here: one step
        Kind kind = Kind::stop;
        Regime junction;           // the junction step's smoothing
        double turn_alpha = 0.0;   // its T1 per unit of corner speed, in that regime
        double sparse_cap = 0.0;   // closed-form corner speed in the sparse regime (decides smoothness)
        double tight_cap = 0.0;    // ... or in its tolerance's regime where faster (as set_junction may pass it)
        double corner_cap = 0.0;   // closed-form speed limit of the corner (one speed both sides)
        CornerBound cap_bound = CornerBound::feed;
        double learned_cap = 0.0;  // lowered where the exact check failed (+inf: none)
        // Backward pass.
        double entry_max = 0.0, exit_max = 0.0;
        bool entry_end_limited = true, exit_end_limited = true;  // by the stop at the end of the known path
        // Forward pass: the plan. Legs at a, p, b last x0, xp, x1 (merged legs: 0).
        double a = 0.0, p = 0.0, b = 0.0;
        double x0 = 0.0, xp = 0.0, x1 = 0.0;
        double rest = 0.0;         // stop: at rest after the stop step until the next start step
        bool unfit = false;        // no legs at these speeds cover it (fits() is not monotone in the speeds)
        bool planned_stop = false; // it ended in a stop when it was planned (exit_is_stop then)
        bool unchecked = false;    // planned by replan's last resort, after no plan passed the check
        double next_a = 0.0;       // the speed after the junction (the next segment's a)
        double predicted_error = 0.0;  // the check's closest approach at the junction
        double checked_reach = std::numeric_limits<double>::infinity();  // how far after the junction (s) its last check looked
        CornerBound bound = CornerBound::feed;  // what limited the speed at the junction
        int bound_axis = -1;
        double enter = 0.0;        // forward pass: its entry step's centre, s (timeline clock)
        double width = 0.0;        // the widest kernel of its legs when build_legs last made them

        // The length each block gives up at corner speed v, and the longest it may.
        double overlap_at(double v) const { return kind == Kind::corner && v > 0.0 ? std::min(overlap, v * overlap_tk) : 0.0; }
        double overlap_most() const { return kind == Kind::corner ? overlap : 0.0; }
        // Tk as planned: the leg across the corner, between its two steps (0: one step).
        double overlap_time() const { return b > 0.0 ? overlap_at(b) / b : 0.0; }
    };

    // A step of the plan: velocity change, the box of its first stage, its kernel.
    struct Step {
        AxisVector dv = AxisVector::Zero();
        double box = 0.0;
        double t2 = 0.0;
        Kernel kernel;
        bool own = false;  // sized to itself (StepShape::own)
        bool gapped = false;  // StepShape::gapped
        StepShape shape() const {
            return {box, dv.norm() > 0.0 ? AxisVector(dv.normalized()) : AxisVector::Zero(), t2, -1.0, own, gapped};
        }
    };
    // The step after the frozen one, as the plan has it now.
    enum class StepKind : std::uint8_t { ramp, junction, stop, start };
    struct NextStep {
        Step step;
        StepKind kind = StepKind::ramp;
        double centre = 0.0;      // seconds from the timeline's now
        double speed_after = 0.0; // command speed of the leg it starts (0: at rest)
    };

    // Where the motion stands: the last step whose kernel has started ("frozen") and the leg
    // after it. Everything after it may still change.
    struct Frozen {
        bool moving = false;     // a leg is under way after the frozen step
        bool any = false;        // a step has frozen since the last reset
        bool junction = false;   // the frozen step is a corner between two segments (not a ramp)
        bool start = false;      // the frozen step is the front segment's start from rest
        double speed = 0.0;      // that leg's command speed
        Step step;               // the frozen step
        std::int64_t tick = 0;   // its centre: tick * period + offset
        double offset = 0.0;
        double consumed = 0.0;   // that leg starts this far into the front segment
        double rest = 0.0;       // at rest: the next start step comes at least this long after it
    };

    // i <= count_ <= the ring's size: one wrap at most (no division: seg() is called millions of times).
    std::size_t ring(std::size_t i) const {
        const std::size_t k = head_ + i;
        return k < segments_.size() ? k : k - segments_.size();
    }
    Segment& seg(std::size_t i) { return segments_[ring(i)]; }
    const Segment& seg(std::size_t i) const { return segments_[ring(i)]; }
    // What is left of it for its legs: less what the motion used; less the overlaps at its ends,
    // the longest they may be (for the estimates; legs_length() at the speeds).
    double seg_length(std::size_t i) const {
        const double rest = i == 0 ? seg(0).length - frozen_.consumed : seg(i).length - seg(i - 1).overlap_most();
        return i + 1 < count_ ? rest - seg(i).overlap_most() : rest;
    }
    // The length its legs cover entered at a and left at b (the overlaps at those corner speeds).
    double legs_length(std::size_t i, double a, double b) const {
        const double rest = i == 0 ? seg(0).length - frozen_.consumed : seg(i).length - seg(i - 1).overlap_at(a);
        return i + 1 < count_ ? rest - seg(i).overlap_at(b) : rest;
    }
    double target(std::size_t i) const { return std::min(seg(i).feed * rate_, seg(i).feed_max); }
    bool entry_is_stop(std::size_t i) const { return i == 0 ? !frozen_.moving : seg(i - 1).kind == Kind::stop; }
    bool exit_is_stop(std::size_t i) const { return i + 1 == count_ || seg(i).kind == Kind::stop; }
    // Asked for, forced by a check or a hold, or a reversal: the junction after it is a stop
    // whatever the blocks around it are (junction_caps).
    static bool stops_whatever_follows(const Segment& s) {
        return s.exact_stop || s.forced_stop || s.hold_split || s.hold_end || s.turn.reversal;
    }
    // entry_shape(i, a) is entry_shape(i, 1) with its box times a: a start, a corner at one speed
    // (not the frozen step, not a dense junction, whose turn changes with the speed).
    bool entry_scales(std::size_t i) const {
        return !(i == 0 && frozen_.moving) && (entry_is_stop(i) ? !sized(i) : seg(i - 1).kind != Kind::dense);
    }

    // Regimes and steps.
    // A dense run's regime for the tolerance epsilon: its jerk stage that of the axes moving
    // `along` it (T2_d = max 2 h_a / J_a over them), every axis' box within J_a T2_d / 2. (Over every
    // axis, a slow-jerk axis widened the stage of runs it takes no part in: firtp_cliffs seed 2
    // program 293, +86 % with the tolerance raised a quarter; now 24 % faster and no cliff.)
    Regime dense_regime(double epsilon, const AxisVector& along) const;
    Regime axes_regime(unsigned mask) const;  // dense_regime's for the axes in mask (bit a: axis a)
    // A sparse regime of the axes moving `along` (or in mask): T2 = max A / J over them, every
    // other axis' box held to J T2; sparse_ where that is every axis' T2 or none limits jerk.
    Regime sparse_regime(const AxisVector& along) const { return sparse_axes(axes_of(along)); }
    Regime sparse_axes(unsigned mask) const;
    // A sparse block's own regime (its start, ramps and stop, all along u): sparse_regime(u) in the
    // shorter of the stage its acceleration along u needs, a_u max_a |u_a| / J_a = a_u u_jerk, and
    // its feed_stage.
    Regime own_regime(const Segment& s) const;
    // A corner's between sparse blocks s and n: sparse_regime of both blocks' axes, in at most the
    // longer of their feed stages. As sparse_estimate() judges a block next to a dense one
    // (next_to_run): in at most the stage of their reach over both blocks' lengths, as long or
    // longer. (Judged in the corner's own stage, the two 0.025 mm chords at the 90 degree turn
    // between two arcs of arcs.ngc, each beside a dense run, were estimated faster sparse, 3.52
    // against 3.24 mm/s, and pinned the runs: 6.272 -> 6.309 s at jerk 1e5.)
    Regime corner_regime(const Segment& s, const Segment& n, bool next_to_run = false) const;
    // sqrt(2 v u_jerk): the stage at which a step along u of twice the block's speed v (a
    // reversal) takes T1 = T2 / 2 (a = sqrt(2 v / u_jerk)). A longer stage only adds to its
    // steps' kernels; so raising an acceleration limit beyond it changes nothing. v is its feed,
    // or, on a block too short to reach it, its reach: the top speed of a move from rest to rest
    // over its length L with the jerk alone, L = 2 v sqrt(v u_jerk) (reach_stage). (Sized to the
    // feed, a short block's stage grew with an acceleration limit up to the feed's, far longer
    // than its steps need: issue 13's cliffs, docs/BENCHMARKS.md.)
    double feed_stage(const Segment& s) const;
    double reach_stage(const Segment& s, double length) const;  // feed_stage() as if s were `length` long
    Regime capped(Regime r, double t2) const;  // r in a stage of at most t2, every box within J t2
    void set_regime(Segment& s, const Regime& r) const { s.regime = r, s.alpha = box(s.u, r); }  // and its alpha
    static Regime stretched(Regime r, double t2) {  // r's boxes in a longer stage
        r.t2 = t2;
        return r;
    }
    unsigned axes_of(const AxisVector& along) const;
    // The regime of the junction between a block (in `before`) and the next where either is
    // dense: smoothed as the dense run is, the wider jerk stage of two (between sparse blocks:
    // corner_regime).
    Regime junction_regime(bool before_dense, const Regime& before, bool after_dense, const Regime& after) const;
    double box(const AxisVector& dv, const Regime& regime) const;  // max_a |dv_a| / cap_a
    Step make_step(const AxisVector& dv, const Regime& regime) const;
    Step ramp_step(std::size_t i, double dv) const;  // along segment i, in its regime
    Regime in_ramp_regime(std::size_t i) const { return shares(seg(i).in_ramp) ? ramp_on_block(i, seg(i).in_ramp) : sparse_ramp(i, seg(i).in_ramp); }
    Regime out_ramp_regime(std::size_t i) const { return shares(seg(i).out_ramp) ? ramp_on_block(i, seg(i).out_ramp) : sparse_ramp(i, seg(i).out_ramp); }
    static bool shares(const Regime& ramp) { return ramp.t2 >= 0.0 && !ramp.sparse; }  // a dense run's regime
    // A block's ramp outside a dense run's regime, next to the junction whose ramp regime is
    // `end`: its own boxes, in that junction's sparse corner stage where it is longer than its own
    // (set_junction), so the two share a moving average. A short block's two ramps lie side by
    // side: both take the longer of its corners' stages. (A long block's both did too: its ramp
    // up from a corner of 48 ms, in the 54 ms of the corner it ramps down into, kept its kernel
    // 36 ms apart from the first corner's: firtp_cliffs seed 3 program 255, blended at a quarter
    // looser tolerance, 0.834 -> 0.867 s; now 0.834 -> 0.839 s.)
    Regime sparse_ramp(std::size_t i, const Regime& end) const {
        const Segment& s = seg(i);
        auto longer = [](double t2, const Regime& r) { return r.t2 >= 0.0 && r.sparse ? std::max(t2, r.t2) : t2; };
        const double t2 = longer(s.regime.t2, end);
        return stretched(s.regime, s.short_block ? longer(longer(t2, s.in_ramp), s.out_ramp) : t2);
    }
    // A ramp on block i sharing a corner's regime; where the block shares the corners at both its
    // ends, each ramp's boxes up to J T2 / 2 (up from one corner and down into the next within T2).
    Regime ramp_on_block(std::size_t i, const Regime& ramp) const;
    Regime ramp_sharing(const Regime& corner) const;  // a ramp sharing the corner's jerk stage: boxes up to J T2 (set_junction)
    bool tight_pays(std::size_t i, const Regime& tight, double tight_alpha, double cap, const Regime& machine, double machine_alpha,
                    double machine_cap) const;
    double peak_estimate(std::size_t k, double v, double alpha) const;
    double blend_loss(std::size_t i, const Regime& regime, double turn_alpha, double v) const;  // corner i at v: time lost, s
    double stop_loss(std::size_t i) const;                                                       // a stop there: time lost, s
    bool stop_pays(std::size_t i, double v) const;  // sparse corner i passed at v loses more than a stop there, by estimate
    // Whether corner i stops: both planned (lookahead_stop.cpp).
    struct Blend {  // what set_stop() changes of a junction set as a blend
        Kind kind;
        double overlap, corner_cap;
        CornerBound cap_bound;
        Regime junction;
        double turn_alpha;
        Regime out_ramp, in_ramp;
    };
    void set_stop(std::size_t i, CornerBound why);
    void stop_if_faster(std::size_t i);
    double pair_entry(std::size_t i) const;  // pair_time's entry speed of block i (-1: from rest)
    double pair_time(std::size_t i, double* left = nullptr) const;  // (left: block i + 1's exit speed)
    void class_if_faster(std::size_t i);  // the newest block i + 1, dense after sparse i: sparse where planned faster
    CornerBound stop_bound(const Segment& s) const {  // what the report says of a stop
        return s.cap_bound == CornerBound::stop_pays && !stops_whatever_follows(s) ? CornerBound::stop_pays : CornerBound::stop;
    }
    Step in_ramp_step(std::size_t i, double dv) const { return make_step(dv * seg(i).u, in_ramp_regime(i)); }   // a -> p
    Step out_ramp_step(std::size_t i, double dv) const { return make_step(dv * seg(i).u, out_ramp_regime(i)); }  // p -> b
    // The start and the stop of a block in the machine's regime are sized to themselves
    // (sized_kernel, kernel.hpp): nothing shares their moving average.
    // (Not the stop a hold places: place_hold_stop finds it with the machine's shared jerk stage.)
    bool sized(std::size_t i) const { return sized_ && seg(i).regime.sparse && !seg(i).hold_split && !seg(i).hold_end; }
    StepShape sized_shape(std::size_t i, double v, const AxisVector& direction) const;
    void resize_sized(std::size_t i, double v, StepShape& shape) const;  // sized_shape()'s box and t2 at speed v
    Step sized_step(std::size_t i, double dv) const;  // dv along u
    Step junction_step(std::size_t i) const;         // after segment i, at the plan's speeds (not a stop); overlapped: the first
    Step overlap_fall(std::size_t i) const;          // an overlapped junction's second step: segment i's pulse falls
    bool overlapped(std::size_t i) const { return i + 1 < count_ && seg(i).overlap_most() > 0.0; }
    // ... and planned so: two steps and a leg between them (a corner at speed 0 is one step).
    bool split(std::size_t i) const { return overlapped(i) && seg(i).b > 0.0; }
    // That leg's displacement as planned (it lasts seg(i).overlap_time()).
    AxisVector overlap_delta(std::size_t i) const { return (seg(i).u + seg(i + 1).u) * seg(i).overlap_at(seg(i).b); }
    Step stop_step(std::size_t i) const;             // segment i's stop at its end
    Step entry_step(std::size_t i) const;            // the step that starts segment i (after the frozen one: it)
    StepShape entry_shape(std::size_t i, double a) const;
    StepShape exit_shape(std::size_t i, double b) const;

    // Geometry and caps.
    void link(std::size_t i);               // junction after segment i: turn, kind, caps
    void set_turn(Segment& s, const AxisVector& next_u) const;  // s.turn towards next_u, and its turn_box
    void classify(std::size_t i);           // dense or not, from its length and its junctions
    bool smooth_dense(std::size_t i, bool only_wider = false);  // dense i: its regime, at run_epsilon (true: set)
    double run_epsilon(std::size_t i) const;  // ... the tolerance that keeps
    void resmooth_run(std::size_t i);         // the run's narrowed blocks before dense i, as it grew (and regime_change_)
    void junction_caps(std::size_t i);      // regime and corner cap of the junction after i (and ramp_change_)
    void set_junction(std::size_t i);       // ... those themselves
    void set_overlap(std::size_t i);        // ... and its overlap (Segment::overlap)
    bool smooth(std::size_t i) const;       // junction i does not slow the blocks down
    bool slower_long(std::size_t k, std::size_t i) const;  // k is a long block slower than i
    double sparse_estimate(std::size_t i) const;  // short block i: speed planned sparse, estimated
    bool run_ends_next(std::size_t i) const;     // a stop asked for ends the run a block beyond i
    double dense_epsilon(std::size_t i) const;   // the tolerance i's dense regime keeps
    double dense_estimate(std::size_t i) const;   // ... and planned dense
    double room_cap(std::size_t i, double alpha) const;  // dense i: highest c with c alpha <= L/c

    // Passes.
    // From `last` down while the bounds change, and at least to a junction resmooth_run changed
    // (regime_change_); returns the first segment whose bounds changed (`last` at least). Below `settled` the fields are as the last pass found them (only their
    // flags may follow a change). The flags are final_for_start()'s alone: a segment whose flags
    // alone changed plans as before (a join of 16 chords re-planned 207 blocks behind them for a
    // flag, where 76-92 changed speed).
    std::size_t backward(std::size_t last, std::size_t settled = 0);
    // The same pass resumable (a join's, over several periods): `next` segments left to go down
    // from, the lowest changed so far (count_: none).
    struct Backward {
        std::size_t next = 0, last = 0, settled = 0, changed = 0;
    };
    bool backward_some(Backward& w, std::size_t most);  // at most `most` junctions; true: the pass ended
    double corner_exit_cap(std::size_t i) const;  // a corner's exit bound but for the next block's entry
    bool exit_end(std::size_t i) const;  // whether segment i's exit_max depends on the end of the known path
    bool settled(std::size_t i) const;   // junction i stays as it is whatever blocks come next
    bool refresh_end_flags(std::size_t i);  // its end-limited flags from its bounds now; true if they changed
    std::size_t refresh_end_flags_below(std::size_t i);  // segments i - 1, i - 2, ... while they change; the lowest changed (i: none)
    void forward(std::size_t from);
    void plan_segment(std::size_t i, double entry);
    void link_next_a(std::size_t i);  // the segment before i: its next_a, and its rest after a stop
    double entry_for(std::size_t i) const;  // the forward entry speed of segment i
    double max_entry(std::size_t i, double exit_max) const;
    // What dense_probe needs of junction i that does not depend on the speeds (found once a search).
    struct DenseJunction {
        std::size_t i = 0;
        const Segment* s = nullptr;
        const Segment* n = nullptr;
        double length = 0.0;      // seg_length(i)
        bool bounded = false;     // a turn with a tolerance: the estimate is checked
        AxisVector m = AxisVector::Zero();  // the turn's bisector, unit(u + u')
        double epsilon = 0.0;     // the tolerance the estimate is held to
        // The width of the step entering segment i at b, its case found once: the frozen step's
        // (fixed), b * scale + t2, or (dense before) a junction step's box found at each speed + t2.
        bool width_fixed = false;
        const Segment* dense_before = nullptr;
        double width_scale = 0.0, width_add = 0.0;
    };
    DenseJunction dense_junction(std::size_t i) const;
    // Whether the dense junction after j.i passes at speeds b before it and a after it.
    search::Probe dense_probe(const DenseJunction& j, double b, double a) const;
    double dense_exit_max(std::size_t i, double next_entry_max) const;
    ProfileInput profile_input(std::size_t i, double a, double b) const;
    bool fits(std::size_t i, double a, double p, double b) const;
    // What a memoized step read (Fitting::key and the step's own inputs), compared whole.
    struct MemoKey {
        std::array<double, 8 * max_axes + 32> values;  // (only the first `size` are ever read)
        int size = -1;                                  // -1: nothing kept
        void put(double x) { values[static_cast<std::size_t>(size++)] = x; }
        bool same(const MemoKey& other) const {
            return size == other.size && std::equal(values.begin(), values.begin() + size, other.values.begin());
        }
        void keep(const MemoKey& other) {
            std::copy(other.values.begin(), other.values.begin() + other.size, values.begin());
            size = other.size;
        }
    };
    // profile_input() and fits() of segment i at many speeds (a search): the parts that do not
    // depend on the speeds are found once, the rest as profile_input() finds them.
    class Fitting {
    public:
        Fitting(const Lookahead& lookahead, std::size_t i);
        Fitting(const Fitting&) = delete;  // in_ points at its own gaps_
        Fitting& operator=(const Fitting&) = delete;
        const ProfileInput& input(double a, double b);
        bool operator()(double a, double p, double b) { return profile_legs(la_.rules_, input(a, b), a, p, b).fits; }
        search::Probe probe(double a, double p, double b) {
            const ProfileLegs legs = profile_legs(la_.rules_, input(a, b), a, p, b);
            return {legs.fits, legs.margin};
        }
        // Everything input() reads but the speeds, as numbers (how many): equal keys, equal inputs.
        MemoKey key() const;

    private:
        const Lookahead& la_;
        std::size_t i_;
        ProfileInput in_;
        bool entry_fixed_ = false;   // the frozen step: the same at any speed
        bool out_sized_ = false;     // the exit is a sized stop: exit_shape() at each speed
        bool entry_scaled_ = false;  // box = a * in_scale_ (else: entry_shape() at each speed)
        double in_scale_ = 0.0, out_scale_ = 0.0;  // the exit's box = b * out_scale_
        bool corner_in_ = false, corner_out_ = false;
        GapMemo gaps_;  // the directions stay the same unless the entry is a dense junction
    };
    // Block k planned from entry a (< 0: from rest) to at most `exit` (pair_time, lookahead_stop.cpp).
    double block_time(Fitting& f, std::size_t k, double a, double exit, double& entered, double& left) const;

    // sampled_corner_speed() (jerk_norm_, the period) by its other arguments: link() and classify()
    // ask again about junctions that have not changed. Direct-mapped on the arguments' bits.
    struct CornerMemo {
        std::array<double, 5> args{};
        double answer = 0.0;
        bool used = false;
    };
    mutable std::array<CornerMemo, 32> corner_memo_{};
    double sampled_speed(double alpha, double t2, double s, double du, double epsilon) const;

    // dense_regime()'s last tolerance: its h per axis, the axes that limit jerk, the regime of
    // them all, and the last other answer (a program keeps its tolerance and its axes for many
    // blocks).
    mutable double regime_epsilon_ = std::numeric_limits<double>::quiet_NaN();
    mutable AxisVector regime_h_ = AxisVector::Zero();
    mutable unsigned regime_all_ = 0;
    mutable Regime regime_wide_{};
    mutable unsigned regime_mask_ = ~0u;
    mutable Regime regime_answer_{};
    // sparse_axes()'s last answer other than sparse_.
    mutable unsigned sparse_mask_ = ~0u;
    mutable Regime sparse_answer_{};

    // max_entry()'s last search per ring slot and all it read (Fitting::key, feed_max, exit_max):
    // the backward pass asks again where nothing changed, to see that nothing did.
    struct EntryMemo {
        MemoKey key;
        double answer = 0.0;
    };
    mutable std::vector<EntryMemo> entry_memo_;
    // plan_segment()'s last sparse plan per ring slot and all it read (Fitting::key and the
    // speeds and flags below): forward() plans blocks again whose end-of-path flags alone changed.
    struct PlanMemo {
        MemoKey key;
        double a = 0.0, p = 0.0, b = 0.0, x0 = 0.0, xp = 0.0, x1 = 0.0;
        bool unfit = false, ramped_on = false;
    };
    std::vector<PlanMemo> plan_memo_;

    // Motion.
    double frozen_centre() const;           // seconds from the timeline's now
    // Earliest centre (s from now) of the start step `half` wide of segment i (0: the front),
    // after the stop step centred at `stop` (s from now): the kernel starts on the first sample at
    // which the stop has settled and segment i's dwell has passed.
    double start_after_stop(std::size_t i, double stop, const Step& stop_step, double half) const;
    double on_tick_grid(double t) const;  // the first sample at or after t (s from now)
    NextStep next_step() const;
    bool final_for_start() const;
    bool front_final() const;  // the front's next steps no longer depend on the end of the known path
    void freeze(const NextStep& next);
    void freeze_overlap(const NextStep& next, std::int64_t tick, double offset);  // both steps of an overlapped corner
    // `step`, centred at tick * period + offset, is the frozen one; the leg after it at `speed`.
    void enter_front(const Step& step, std::int64_t tick, double offset, double speed, bool junction, const AxisVector& leg_start);
    void pop_front(bool stop);
    void refresh_current_leg();
    // false: `undoable` (a batch of blocks) and no plan passed short of the last resort.
    bool replan(std::size_t first_changed, bool undoable = false);
    // replan()'s steps, so a join can take them in separate periods: begin (false: nothing to
    // plan), a forward pass and the motion it changed, then a check; a failed check's remedy
    // (again: plan and check again; undo / kept: return false / true; planned: the last resort),
    // and what bounded each junction once a plan stands.
    struct Replan {
        std::size_t from = 0, changed = 0, kept = 0;  // kept: saved_ holds the accepted plan from here
        bool fallback = false, saved_all = false;
        int attempt = 0;
        std::size_t lowered = 0;  // the corner the last attempt lowered (count_: none), its cap before
        double lowered_cap = 0.0;
        LimitCheck lowered_for;
    };
    enum class Remedy : std::uint8_t { again, undo, kept, planned };
    bool replan_begin(std::size_t first, Replan& r);
    void replan_forward(Replan& r);
    Remedy replan_failed(Replan& r, std::size_t bad, bool undoable);
    // The dense blocks beside junction `bad` whose sparse estimate is more than twice `cap` ramp
    // on their own (sparse_only); false if there was none.
    bool sparse_beside(std::size_t bad, double cap);
    bool replan_run(Replan& r, bool undoable);  // from a forward pass on, to the end
    void replan_passed(const Replan& r);
    void replan_end(std::size_t from);
    // What add(at_update) or a join left, before a change of rate reads the plan.
    void plan_added() {
        finish_join();
        if (batch_.open) plan_batch();
    }
    void plan_batch();
    // The next step's kernel starts by the timeline's current tick (each commit asks: inline).
    bool next_due() const {
        const double period = parameters_.period;
        const double now = static_cast<double>(timeline_->now()) * period;
        if (!next_known_) find_next(now);
        return next_start_ - now <= 1e-9 * period;
    }
    void find_next(double now) const;
    // The plan from segment `first` on, its corners from where the motion changed (`changed` >=
    // first; count_: nowhere) on; false and *bad: the corner to lower.
    bool check(std::size_t first, std::size_t changed, std::size_t* bad);
    // A check in two parts: its legs and their limits, then the corners (a join's, a few a period).
    // Indices as build_legs() made its arrays; `shift` segments have left the window since.
    struct CheckRun {
        std::size_t from = 0, last = 0, next = 0, shift = 0;
        double begin = 0.0, unchanged_until = 0.0;
        bool sharp = false, one_stage = false;
    };
    enum class Checked : std::uint8_t { failed, passed, corners };
    Checked check_begin(std::size_t first, std::size_t changed, std::size_t* bad, CheckRun& c);
    Checked check_corners(CheckRun& c, std::size_t most, std::size_t* bad);  // at most `most` measured
    bool check_measures(const CheckRun& c, std::size_t i) const;  // corner i (as built) is measured
    // From a segment's entry step to the next segment's: its legs, and a stop's rest.
    static double span(const Segment& s) { return s.x0 + s.xp + s.x1 + (s.kind == Kind::stop ? s.rest : s.overlap_time()); }
    std::size_t context(std::size_t first) const;  // where a check from `first` first builds its legs (a guess)
    // The largest k <= first such that every leg a check from k leaves out has come to rest by
    // `until` (s from now), as far as this build (from `from`) and the segments' widths tell.
    std::size_t covered_from(std::size_t from, std::size_t first, double until);
    // The earliest kernel start of segment k's steps and those after it, among legs_[0, legs) as
    // build_legs(from) made them (k >= from); infinity if they have none.
    double first_kernel_start(std::size_t from, std::size_t k, std::size_t legs) const;
    // Whether segment s makes the same legs as `before` did (build_legs: speeds, durations, steps)
    // and `before`'s were checked.
    static bool same_motion(const Segment& s, const Segment& before);
    // Hold: brake from the motion under way and split the block where the earliest stop falls.
    void place_hold_stop();
    std::size_t hold_stop_index() const;  // the segment the hold's stop ends; count_ if none
    bool hold_stop_placed() const { return hold_stop_index() < count_; }
    bool hold_remnants() const;  // a segment still braking for, split by or ending at a hold's stop
    void replan_from_front(bool resuming);  // after a change of rate (undoing the hold's stop)
    void unsplit();  // resume before the hold's stop began: the split block is whole again
    // The accepted plan of the first `keep` segments (all of them by default), to go back to.
    void take_snapshot(std::size_t keep = static_cast<std::size_t>(-1));
    // The window's reach (lookahead_reach.cpp): blocks beyond it wait (deferred_) and join it in
    // batches as the motion uses it up.
    std::size_t horizon() const;  // the blocks from the front the motion can reach soon
    bool waits_beyond();          // add(): the window reaches far enough, the new block waits
    void defer_beyond(std::size_t keep);  // a change of rate: the blocks after `keep` wait
    void take_waiting();          // the first waiting block, as it came, at ring slot count_
    void rejoin_some();           // at each commit
    std::size_t batch_size() const;    // a batch's blocks: one more than the last join re-planned before them
    std::size_t rejoin_count() const;  // how many waiting blocks join next
    void join_waiting(std::size_t n);  // the first n waiting blocks join (a batch under way: spread)
    // A window still filling under way (blocks come about as fast as the motion uses them): a block
    // waits (filling_) and joins with others in a batch spread over periods.
    bool fills_under_way() const;
    bool gathers() const;      // rejoin_some(): the waiting blocks wait for more
    // A join over several periods (lookahead_reach.cpp), one step a commit: the bounds a few
    // junctions at a time, the forward pass, the check's legs and limits, its corners a few at a
    // time; a batch's, while the motion is under way. Steps freeze meanwhile, before the blocks the
    // join changes (its indices shift: join_popped()).
    struct Join {
        enum class Stage : std::uint8_t { bounds, plan, check, corners } stage = Stage::bounds;
        bool open = false;
        bool undoable = false;  // a batch (its undo: snapshot_)
        bool froze = false;     // a step froze since it opened (its kernel may be wider than any before)
        std::size_t before = 0, lowest = 0;
        std::size_t pops = 0;   // segments that left the window since it opened (snapshot_'s offset)
        Backward bounds;
        Replan plan;
        CheckRun check;
        std::int64_t done = -1;  // tick of the last join's plan: one a period
    } join_;
    void finish_join() {
        while (join_.open) join_step(true);
    }
    // What a join's step changes lies at least this many segments from the front: the next
    // step freezes the front block's exit and reads the two after it. Nearer, the rest at once.
    static constexpr std::size_t join_split_from = 4;
    void join_step(bool whole);   // the next step (whole: all of them)
    std::size_t join_front() const;  // the lowest segment the open join may still change
    void join_popped();           // the front segment left the window: the join's indices shift
    void join_planned(bool planned);
    // The segment at ring slot count_ joins the window as the newest block (add, rejoin).
    void join(Planning when);
    void link_newest();  // join's first half: counted and linked to the block before, not planned
    // Blocks joined after the first `before` (one or a batch): the backward pass from the new end
    // (the junctions before before - 2 were settled), then the end flags of the junction it settles
    // (settle_end_flags), then the plan from the lowest segment whose bounds changed or the
    // junction they joined on, whichever is first (joined_first; as replan()).
    Backward bounds_joined(std::size_t before) {
        const std::size_t low = std::min(count_ - 1, take_regime_change());
        return {count_, low, std::min(low, before >= 2 ? before - 2 : 0), count_};
    }
    void settle_end_flags();
    static std::size_t joined_first(std::size_t before, std::size_t lowest);
    bool plan_joined(std::size_t before, bool undoable = false);
    // What a plan changes beside the segments, for a batch's undo (plan_batch, rejoin_some).
    struct PlanScalars {
        std::size_t ramp_change = 0;
        double max_width = 0.0, context_span = 0.0;
        std::uint64_t unfit = 0;
    };
    PlanScalars plan_scalars() const { return {ramp_change_, max_width_, context_span_, stats_.unfit}; }
    void restore(const PlanScalars& p);
    // A block's segment as it comes: what its own geometry gives, nothing learned, a stop after it.
    void arrive(Segment& s) const;
    // The stop at the window's end is the program's.
    bool end_known() const { return finished_ && deferred_ == 0; }
    void insert_after(std::size_t i, const Segment& s);
    void erase(std::size_t i);
    // Legs of segments [first, count) (and, from segment 0, the timeline's legs before them), in
    // seconds from the timeline's now; leg_of_[i] is segment i's last leg, when_[i] its exit step.
    void build_legs(std::size_t first);

    bool moving() const { return frozen_.moving || !timeline_->idle(); }

    PlannerParameters parameters_;
    MachineLimits limits_;   // what it plans with: smoothing_limits (parameters.hpp)
    MachineLimits machine_;  // what the check measures against: the machine's own
    SpacingRules rules_;
    Regime sparse_;
    Timeline* timeline_;
    double max_width_ = 0.0;
    double width_bound_ = 0.0;  // no segment's width (build_legs) has been larger: covered_from()
    double context_span_ = 0.0;  // how far before `first` the last check needed its legs (s): context()'s guess
    double jerk_norm_ = 0.0;   // |J| over the axes, for the chord margin
    bool sized_ = false;       // an axis limits jerk: starts and stops are sized (sized())
    // The lowest segment whose ramps' regime junction_caps() changed since the last replan (its
    // legs were planned for the old one); SIZE_MAX: none.
    std::size_t ramp_change_ = static_cast<std::size_t>(-1);
    std::size_t regime_change_ = static_cast<std::size_t>(-1);  // lowest junction a resmooth_run changed: bounds from there
    std::size_t take_ramp_change() { return std::exchange(ramp_change_, static_cast<std::size_t>(-1)); }
    std::size_t take_regime_change() { return std::exchange(regime_change_, static_cast<std::size_t>(-1)); }
    double machine_acceleration_ = 0.0;  // |a| within the machine's limits: how far a chord of the samples may stray
    double machine_jerk_ = 0.0;          // |j| likewise (HUGE_VAL: an axis has no jerk limit)
    double hold_bound_ = 0.0;            // hold_time_bound(): a hold comes to rest within it
    double rate_ = 1.0;
    double max_rate_ = 1.0;
    bool held_ = false;
    bool finished_ = false;
    std::int64_t waiting_since_ = -1;  // tick the first step of a start began to wait for the look-ahead
    std::int64_t last_add_tick_ = 0;   // tick of the last add() (start_idle)
    // The next step, kept until the plan changes (next_due() finds it).
    mutable bool next_known_ = false;  // next_start_ holds for the plan as it is
    mutable bool next_is_start_ = false;
    mutable double next_start_ = 0.0;  // the next step's kernel start, s on the timeline's clock
    double excess_ = 0.0;              // the last failed corner's error / tolerance (0: a limit failed)
    LimitCheck limit_failure_;          // the last check's limit sweep (ok: it passed, or looked no further)
    bool order_failure_ = false;        // the last check failed on the order of a leg's kernels (check_begin)
    double pending_dwell_ = 0.0;       // dwell of skipped zero-length blocks: the next block's

    std::size_t capacity_;           // blocks add() takes
    std::vector<Segment> segments_;  // ring: capacity_ + 1 (the spare for a hold's split)
    std::size_t head_ = 0;
    std::size_t count_ = 0;
    std::size_t deferred_ = 0;  // after the window, in ring order: blocks beyond its reach
    std::size_t keep_ = 0;      // the window's reach: waiting blocks join while it holds fewer
    bool filling_ = false;      // blocks wait though the window is short of it (fills_under_way)
    std::uint32_t rejoin_clock_ = 0;  // commits with blocks waiting: the reach is measured every few
    std::uint32_t add_clock_ = 0;     // adds without: likewise
    std::size_t tail_ = 1;  // blocks before the last to join whose bounds that join changed (+ 1)
    PlanScalars undo_;  // what a batch of waiting blocks found, for its undo (with snapshot_)
    AxisVector goal_;
    Frozen frozen_;

    PlannerStats stats_;
    LimitSweep sweep_;
    std::vector<TimedLeg> legs_;        // scratch for checks
    std::vector<std::size_t> leg_of_;   // scratch: index in legs_ of each segment's last leg
    std::vector<std::size_t> leg_begin_;  // scratch: ... of its first (legs_.size() if none)
    std::vector<double> when_;          // scratch: exit step centre of each segment (check clock)
    std::vector<double> enter_;         // scratch: entry step centre of each segment
    std::vector<double> settled_by_;    // scratch (covered_from): when each segment's legs have come to rest
    std::vector<Segment> saved_;        // the accepted plan, restored when a change fails its check
    // A hold's stop placed, or a resume's split undone, changes the segments themselves: the
    // accepted plan is kept whole before, and if no plan after the change passes its check, it
    // goes on and the change is made again at the next tick, from where the motion then is.
    std::vector<Segment> snapshot_;
    std::size_t snapshot_count_ = 0;
    std::size_t snapshot_head_ = 0;
    std::size_t snapshot_cut_ = 0;      // blocks the change left out (defer_beyond): back in on a restore
    // (snapshot_ also keeps the window a batch of waiting blocks found: rejoin_some.)
    bool snapshot_taken_ = false;       // for the replan under way
    bool retry_ = false;                // the change failed: again at the next tick
    // Blocks added at_update since the last plan, and the window as the first of them found it.
    // A batch whose plan fails its check beyond lowering corners is undone and added again block
    // by block: the last resort (keep the accepted plan, start the newest block from rest after
    // it) is one block's. Off the real-time path: the store is allocated by the first batch.
    struct Batch {
        bool open = false;
        std::vector<Block> blocks;
        std::vector<Segment> window;
        std::size_t head = 0, count = 0;
        AxisVector goal;
        double pending_dwell = 0.0;
        PlanScalars plan;
        bool finished = false;
    } batch_;
    void open_batch();
    std::vector<CornerReport> reports_; // ring of corner reports, filled as junctions freeze
    std::size_t report_head_ = 0, report_count_ = 0;
};

}  // namespace firtp
