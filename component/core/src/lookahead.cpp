#include <firtp/lookahead.hpp>

#include <firtp/dense_legs.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <utility>

namespace firtp {

using search::highest;
using search::lowest;
using search::Probe;

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double ramp_on_margin = 1e-9;  // of the target: a start from rest this close to it does not ramp on

AxisVector unit(const AxisVector& v) {
    const double n = v.norm();
    return n > 0.0 ? AxisVector(v / n) : AxisVector::Zero();
}

// Highest speed along direction u that the axis velocity limits (and, for moves of linear axes,
// [TRAJ]MAX_LINEAR_VELOCITY) allow.
double velocity_cap(const MachineLimits& limits, const AxisVector& u) {
    double cap = infinity;
    const bool linear = u.head<3>().norm() > 1e-12 || u.tail<3>().norm() > 1e-12;
    if (linear && limits.max_linear_velocity > 0.0) cap = limits.max_linear_velocity;
    for (int i = 0; i < limits.axes; ++i) {
        const double v = limits.axis[i].max_velocity;
        if (v > 0.0 && std::abs(u[i]) > 0.0) cap = std::min(cap, v / std::abs(u[i]));
    }
    return cap;
}

}  // namespace

const char* describe(CornerBound bound) {
    switch (bound) {
        case CornerBound::feed: return "feed";
        case CornerBound::tolerance: return "tolerance";
        case CornerBound::room: return "block length";
        case CornerBound::lookahead: return "look-ahead";
        case CornerBound::checked: return "checked";
        case CornerBound::stop: return "exact stop";
        case CornerBound::stop_pays: return "stop: faster than blending";
    }
    return "?";
}

Lookahead::Lookahead(const PlannerParameters& parameters, Timeline& timeline, const AxisVector& start)
    : parameters_(parameters), limits_(smoothing_limits(parameters.limits)), machine_(parameters.limits), timeline_(&timeline),
      max_rate_(std::max(parameters.max_rate, 1.0)), capacity_(std::max<std::size_t>(parameters.queue_capacity, 2)),
      segments_(capacity_ + 1),  // one spare: a hold splits a block even when the window is full
      goal_(start), sweep_(4 * segments_.size() + 64), saved_(segments_.size()), snapshot_(segments_.size()) {
    rules_.limits = limits_;
    rules_.t2 = jerk_time(limits_);
    sparse_.t2 = rules_.t2;
    sparse_.sparse = true;
    sparse_.axes = (1u << limits_.axes) - 1u;
    double jerk = 0.0, acc = 0.0;
    bool all_jerk = true;
    for (int i = 0; i < limits_.axes; ++i) {
        const AxisLimits& l = limits_.axis[i];
        sparse_.cap[i] = l.max_acceleration > 0.0 ? l.max_acceleration : infinity;
        if (!(l.max_acceleration > 0.0)) continue;  // an axis the machine does not have (it never moves)
        jerk += l.max_jerk * l.max_jerk;
        acc += l.max_acceleration * l.max_acceleration;
        all_jerk = all_jerk && l.max_jerk > 0.0;
    }
    for (int i = limits_.axes; i < max_axes; ++i) sparse_.cap[i] = infinity;
    jerk_norm_ = all_jerk ? std::sqrt(jerk) : std::sqrt(acc) / parameters_.period;
    // A step along axes without a jerk limit is sized by their acceleration alone (u_jerk 0: one
    // stage). Sizing only where every axis limits jerk left such machines' lone short blocks in a
    // dense regime of the tolerance, slower with a looser one (firtp_cliffs seed 31 program 85).
    sized_ = rules_.t2 > 0.0;
    double machine_acc = 0.0, machine_jerk = 0.0;  // |a|, |j| the limit sweep lets through (its slack is 1e-7 of a limit)
    for (int i = 0; i < machine_.axes; ++i) {
        const double a = machine_.axis[i].max_acceleration * (1.0 + 1e-6), j = machine_.axis[i].max_jerk * (1.0 + 1e-6);
        if (a > 0.0) machine_acc += a * a;
        machine_jerk = j > 0.0 ? machine_jerk + j * j : HUGE_VAL;  // an axis without a jerk limit: none
    }
    machine_acceleration_ = std::sqrt(machine_acc);
    machine_jerk_ = std::sqrt(machine_jerk);
    hold_bound_ = hold_time_bound(parameters_);
    legs_.reserve(4 * segments_.size() + 64);  // a, p, b and an overlap's leg a block
    leg_of_.resize(segments_.size());
    leg_begin_.resize(segments_.size());
    when_.resize(segments_.size());
    enter_.resize(segments_.size());
    settled_by_.resize(segments_.size());
    entry_memo_.resize(segments_.size());
    plan_memo_.resize(segments_.size());
    reports_.resize(64);
}

void Lookahead::reset(const AxisVector& position) {
    ramp_change_ = regime_change_ = static_cast<std::size_t>(-1);
    batch_.open = false;
    join_ = Join{};
    head_ = 0;
    count_ = 0;
    goal_ = position;
    frozen_ = Frozen{};
    finished_ = false;
    deferred_ = 0;
    filling_ = false;
    waiting_since_ = -1;
    pending_dwell_ = 0.0;
}

// ---- Regimes and steps -------------------------------------------------------------------------

Lookahead::Regime Lookahead::dense_regime(double epsilon, const AxisVector& along) const {
    if (!(epsilon == regime_epsilon_)) {
        regime_epsilon_ = epsilon;
        regime_h_ = AxisVector::Zero();
        regime_all_ = 0;
        for (int i = 0; i < limits_.axes; ++i) {
            const AxisLimits& l = limits_.axis[i];
            if (!(l.max_jerk > 0.0) || !(l.max_acceleration > 0.0)) continue;
            // Without a tolerance the swing from -h to +h needs no more than the sparse jerk time.
            regime_h_[i] = std::isfinite(epsilon) ? std::min(l.max_acceleration, std::cbrt(3.0 * epsilon * l.max_jerk * l.max_jerk))
                                                  : 0.5 * l.max_acceleration;
            regime_all_ |= 1u << i;
        }
        regime_mask_ = ~0u;
        regime_wide_ = axes_regime(regime_all_);
    }
    const unsigned mask = axes_of(along) & regime_all_;
    // (Nothing along it limits jerk: the stage of every axis.)
    if (mask == regime_all_ || mask == 0) return regime_wide_;
    if (mask != regime_mask_) regime_mask_ = mask, regime_answer_ = axes_regime(mask);
    return regime_answer_;
}

Lookahead::Regime Lookahead::axes_regime(unsigned mask) const {
    Regime r = sparse_;
    r.sparse = false;
    if (!(rules_.t2 > 0.0)) return r;
    r.t2 = 0.0;
    for (int i = 0; i < limits_.axes; ++i)
        if (mask & (1u << i)) r.t2 = std::max(r.t2, 2.0 * regime_h_[i] / limits_.axis[i].max_jerk);
    // Every axis keeps its jerk in that stage, those that do not move along it too.
    for (int i = 0; i < limits_.axes; ++i)
        if (regime_h_[i] > 0.0) r.cap[i] = std::min(regime_h_[i], 0.5 * limits_.axis[i].max_jerk * r.t2);
    return r;
}

unsigned Lookahead::axes_of(const AxisVector& along) const {
    unsigned mask = 0;
    for (int i = 0; i < limits_.axes; ++i)
        if (along[i] != 0.0) mask |= 1u << i;
    return mask;
}

Lookahead::Regime Lookahead::sparse_axes(unsigned mask) const {
    mask &= sparse_.axes;
    if (mask == sparse_.axes || mask == 0) return sparse_;
    if (mask == sparse_mask_) return sparse_answer_;
    MachineLimits moving = limits_;  // (an axis without a jerk limit has no stage: jerk_time)
    for (int i = 0; i < limits_.axes; ++i)
        if (!(mask & (1u << i))) moving.axis[i].max_jerk = 0.0;
    const double t2 = jerk_time(moving);
    sparse_mask_ = mask;
    Regime& r = sparse_answer_;
    r = sparse_;
    if (!(t2 > 0.0) || t2 >= rules_.t2) return r;  // (nothing along it limits jerk: as every axis)
    r.t2 = t2;
    r.axes = mask;
    // Every axis keeps its jerk in that stage, those that do not move along it too.
    for (int i = 0; i < limits_.axes; ++i)
        if (limits_.axis[i].max_jerk > 0.0 && !(mask & (1u << i))) r.cap[i] = std::min(r.cap[i], limits_.axis[i].max_jerk * t2);
    return r;
}

Lookahead::Regime Lookahead::capped(Regime r, double t2) const {
    if (!(t2 < r.t2) || !(t2 > 0.0)) return r;
    r.t2 = t2;
    for (int i = 0; i < limits_.axes; ++i)
        if (limits_.axis[i].max_jerk > 0.0) r.cap[i] = std::min(r.cap[i], limits_.axis[i].max_jerk * t2);
    return r;
}

double Lookahead::feed_stage(const Segment& s) const { return reach_stage(s, s.length); }

double Lookahead::reach_stage(const Segment& s, double length) const {
    if (!(s.u_jerk > 0.0)) return infinity;
    const double v = std::min(s.feed_max, std::cbrt(length * length / (4.0 * s.u_jerk)));  // (its reach)
    return std::isfinite(v) ? std::sqrt(2.0 * v * s.u_jerk) : infinity;
}

Lookahead::Regime Lookahead::own_regime(const Segment& s) const {
    const Regime r = sparse_regime(s.u);
    const double alpha = box(s.u, r);  // 1 / a_u
    return capped(r, std::min(alpha > 0.0 ? s.u_jerk / alpha : infinity, s.feed_t2));
}

Lookahead::Regime Lookahead::corner_regime(const Segment& s, const Segment& n, bool next_to_run) const {
    const double t2 = next_to_run ? std::max(reach_stage(s, s.length + n.length), reach_stage(n, s.length + n.length))
                               : std::max(s.feed_t2, n.feed_t2);
    return capped(sparse_regime(s.u.cwiseAbs() + n.u.cwiseAbs()), t2);
}

Lookahead::Regime Lookahead::junction_regime(bool before_dense, const Regime& before, bool after_dense,
                                             const Regime& after) const {
    if (before_dense && after_dense) return after.t2 > before.t2 ? after : before;
    return before_dense ? before : after;
}

double Lookahead::box(const AxisVector& dv, const Regime& regime) const {
    double t = 0.0;
    for (int i = 0; i < limits_.axes; ++i)
        if (std::isfinite(regime.cap[i])) t = std::max(t, std::abs(dv[i]) / regime.cap[i]);
    return t;
}

Lookahead::Step Lookahead::make_step(const AxisVector& dv, const Regime& regime) const {
    Step s;
    s.dv = dv;
    s.box = box(dv, regime);
    s.t2 = regime.t2;
    s.kernel = two_stage(s.box, s.t2);
    s.gapped = regime.sparse;
    return s;
}

Lookahead::Step Lookahead::ramp_step(std::size_t i, double dv) const { return make_step(dv * seg(i).u, seg(i).regime); }

Lookahead::Step Lookahead::junction_step(std::size_t i) const {
    const Segment& s = seg(i);
    if (split(i)) return make_step(s.next_a * seg(i + 1).u, s.junction);  // the next pulse rises
    return make_step(s.next_a * seg(i + 1).u - s.b * s.u, s.junction);
}

Lookahead::Step Lookahead::overlap_fall(std::size_t i) const {
    const Segment& s = seg(i);
    return make_step(-s.b * s.u, s.junction);
}

StepShape Lookahead::sized_shape(std::size_t i, double v, const AxisVector& direction) const {
    StepShape shape{0.0, direction, 0.0, seg(i).u_box, true};
    resize_sized(i, v, shape);
    return shape;
}

void Lookahead::resize_sized(std::size_t i, double v, StepShape& shape) const {
    const Segment& s = seg(i);
    const Kernel k = sized_kernel(v, s.alpha, s.u_jerk);
    shape.box = k.a, shape.t2 = k.b;
}

Lookahead::Step Lookahead::sized_step(std::size_t i, double dv) const {
    const Segment& s = seg(i);
    Step st;
    st.dv = dv * s.u;
    st.kernel = sized_kernel(std::abs(dv), s.alpha, s.u_jerk);
    st.box = st.kernel.a;
    st.t2 = st.kernel.b;
    st.own = true;
    return st;
}

Lookahead::Step Lookahead::stop_step(std::size_t i) const { return sized(i) ? sized_step(i, -seg(i).b) : ramp_step(i, -seg(i).b); }

Lookahead::Step Lookahead::entry_step(std::size_t i) const {
    if (i == 0 && frozen_.moving) return frozen_.step;
    if (entry_is_stop(i)) return sized(i) ? sized_step(i, seg(i).a) : ramp_step(i, seg(i).a);
    return split(i - 1) ? overlap_fall(i - 1) : junction_step(i - 1);
}

StepShape Lookahead::entry_shape(std::size_t i, double a) const {
    const Segment& s = seg(i);
    if (i == 0 && frozen_.moving) return frozen_.step.shape();
    if (entry_is_stop(i)) return sized(i) ? sized_shape(i, a, s.u) : StepShape{a * s.alpha, s.u, s.regime.t2, s.u_box, false, s.regime.sparse};  // the start
    const Segment& prev = seg(i - 1);
    if (prev.kind == Kind::dense) return make_step(a * s.u - prev.b * prev.u, prev.junction).shape();  // speed and turn at once
    if (overlapped(i - 1)) return {a * prev.alpha, -prev.u, prev.junction.t2, prev.u_box, false, prev.junction.sparse};  // the pulse before falls
    return {a * prev.turn_alpha, prev.turn.direction, prev.junction.t2, prev.turn_box, false, prev.junction.sparse};  // the corner, one speed both sides
}

StepShape Lookahead::exit_shape(std::size_t i, double b) const {
    const Segment& s = seg(i);
    if (exit_is_stop(i)) return sized(i) ? sized_shape(i, b, -s.u) : StepShape{b * s.alpha, -s.u, s.regime.t2, s.u_box, false, s.regime.sparse};  // the stop
    if (overlapped(i)) {  // the next pulse rises
        const Segment& n = seg(i + 1);
        return {b * n.alpha, n.u, s.junction.t2, n.u_box, false, s.junction.sparse};
    }
    return {b * s.turn_alpha, s.turn.direction, s.junction.t2, s.turn_box, false, s.junction.sparse};
}

// ---- Geometry and caps -------------------------------------------------------------------------

double Lookahead::room_cap(std::size_t i, double alpha) const {
    if (!(alpha > 0.0)) return infinity;
    return std::sqrt(seg_length(i) / alpha);
}

bool Lookahead::slower_long(std::size_t k, std::size_t i) const {
    return !seg(k).short_block && seg(k).feed_max < seg(i).feed_max;
}

bool Lookahead::smooth(std::size_t i) const {
    const Segment& s = seg(i);
    return s.kind != Kind::stop && s.sparse_cap >= std::min(s.feed_max, seg(i + 1).feed_max);
}

// A short block planned sparse hosts the steps at both its ends in its one leg, about T2 apart
// (spacing rules): it keeps the lower of its corners' sparse caps, or ramps from its entry
// corner's cap to its exit corner's (from or to rest at a stop) through a peak it has room for (a
// trapezoid at the acceleration along it, plus T2), whichever is faster on average. (Ramping only
// from rest to rest left a block between a fast and a slow corner to be classified dense and
// crawl: seed 7, program 199, +14.5 % with every tolerance a quarter larger.)
double Lookahead::sparse_estimate(std::size_t i) const {
    const Segment& s = seg(i);
    const double length = seg_length(i);
    const bool entry = i > 0 && !entry_is_stop(i), exit = !exit_is_stop(i);
    const double in = entry ? std::min(seg(i - 1).tight_cap, s.feed_max) : 0.0;
    const double out = exit ? std::min(s.tight_cap, s.feed_max) : 0.0;
    const Regime& own = s.own;
    const double alpha = box(s.u, own);  // 1 / the acceleration along u
    // v^2 changes by 2 L / alpha at most over the block: the higher end comes down to what it allows.
    const double reach = alpha > 0.0 ? 2.0 * length / alpha : infinity;
    const double v0 = std::min(in, std::sqrt(out * out + reach)), v1 = std::min(out, std::sqrt(v0 * v0 + reach));
    const double peak = std::min(s.feed_max, std::sqrt(0.5 * (reach + v0 * v0 + v1 * v1)));
    // The jerk stage each end's step adds beyond its box: at a corner, the corner's stage (the
    // ramps beside it share it: sparse_ramp; beside a dense block, corner_regime's longer one);
    // at a start or stop sized to itself, its own, from the peak (far below T2 where the peak is
    // slow: seed 7 program 260, a 0.05 mm G61 block on an axis with T2 = 93 ms, estimated at T2
    // and classified dense: +245 % with every tolerance a quarter larger). (On arrival the next
    // block is not classed yet, link(): its side counts as dense only where a block is classed
    // again later, as a check's remedy does.)
    const bool sized_ends = sized_ && !s.hold_split && !s.hold_end && peak > 0.0 && std::isfinite(peak);
    const double sized_jerk = sized_ends ? std::min(own.t2, std::max(0.0, sized_kernel(peak, alpha, s.u_jerk).width() - peak * alpha)) : own.t2;
    const double entry_jerk = entry ? std::max(own.t2, corner_regime(seg(i - 1), s, seg(i - 1).dense).t2) : sized_jerk;
    const double exit_jerk = exit ? std::max(own.t2, corner_regime(s, seg(i + 1), seg(i + 1).dense).t2) : sized_jerk;
    const double jerk_time = 0.5 * (entry_jerk + exit_jerk);
    double corners = s.feed_max;
    if (jerk_time > 0.0) corners = std::min(corners, length / jerk_time);
    if (entry) corners = std::min(corners, in);
    if (exit) corners = std::min(corners, out);
    if (!(alpha > 0.0)) return std::max(corners, s.feed_max);
    const double ramping = (2.0 * peak - v0 - v1) * alpha;
    const double cruise = std::max(0.0, length - 0.5 * alpha * (2.0 * peak * peak - v0 * v0 - v1 * v1)) / peak;
    const double ramps = length / (ramping + cruise + jerk_time);
    return std::max(corners, std::min(ramps, s.feed_max));
}

double Lookahead::sampled_speed(double alpha, double t2, double s, double du, double epsilon) const {
    const std::array<double, 5> args{alpha, t2, s, du, epsilon};
    std::uint64_t hash = 0;
    for (double x : args) hash = (hash ^ std::bit_cast<std::uint64_t>(x)) * 0x100000001b3ull;
    CornerMemo& memo = corner_memo_[(hash >> 32) % corner_memo_.size()];
    if (!memo.used || memo.args != args) {
        memo.args = args;
        memo.answer = sampled_corner_speed(alpha, t2, s, du, jerk_norm_, parameters_.period, epsilon);
        memo.used = true;
    }
    return memo.answer;
}

// Planned dense, its corners' steps must fit the legs on both sides (room) and, with the jerk
// stage each junction would then get (the wider of its blocks' dense regimes), keep about half the
// tolerance for the step itself (lookahead.hpp, Regime). Across a straight junction from a dense
// neighbour k next to a stop, the block's one speed v is also bound by k's: the junction's step
// from k's speed v_k (at most its room) shares k's one leg with k's start or stop, half each,
// (v_k alpha_k + (v - v_k) alpha_j) / 2 <= L_k / v_k. (Unseen, an 18.9 mm block in line after a
// 0.071 mm one from rest was dense at 9.3 mm/s, twice the short block's speed: firtp_cliffs seed 2
// program 161, 2.108 s; now sparse, 0.368 s.) Only where the block is at least dense_neighbour_ratio
// times as long as k: nearer, the sparse estimate overrated the other class (seed 3 program 126,
// a 1.41 mm block after a 0.37 mm one, 0.3065 -> 0.3292 s).
double Lookahead::dense_estimate(std::size_t i) const {
    double v = seg(i).feed_max;
    const Regime own = dense_regime(dense_epsilon(i), seg(i).u);
    for (std::size_t j : {i - 1, i}) {
        if (j >= i + 1 || j + 1 >= count_ || seg(j).kind == Kind::stop) continue;  // (i - 1 wraps for i = 0)
        const std::size_t k = j == i ? i + 1 : j;  // the neighbour across junction j
        if (slower_long(k, i)) v = std::min(v, seg(k).feed_max);
        const Segment& s = seg(j);
        const Regime r = j == i ? junction_regime(true, own, seg(i + 1).dense, seg(i + 1).regime)
                                : junction_regime(s.dense, s.regime, true, own);
        const Segment& n = seg(k);
        if (s.turn.beta < straight_angle && n.dense && (k < i ? entry_is_stop(k) : exit_is_stop(k)) && !(k == 0 && frozen_.moving) &&
            seg(i).length >= dense_neighbour_ratio * n.length) {
            const double alpha_j = box(seg(i).u, r), vk = std::min(n.feed_max, room_cap(k, n.alpha));
            if (alpha_j > 0.0 && vk > 0.0) v = std::min(v, vk + std::max(0.0, 2.0 * seg_length(k) / vk - vk * n.alpha) / alpha_j);
        }
        const double alpha = box(s.turn.du, r);
        if (!(alpha > 0.0)) continue;
        v = std::min(v, std::sqrt(std::min(seg_length(j), seg_length(j + 1)) / alpha));
        if (s.turn.beta >= straight_angle && std::isfinite(s.tolerance))
            v = std::min(v, sampled_speed(alpha, r.t2, s.turn.s, s.turn.du.norm(), s.tolerance));
    }
    return v;
}

// The tolerance a block's dense regime keeps: its own, at its exit corner; where it ends in an
// exact stop (no tolerance), its entry corner's. (Taken as unbounded, the regime's T2 grew to the
// machine's A / J, 0.2 s on a 0.64 mm G61 block: firtp_cliffs seed 2 program 169, +55 % with
// every tolerance a quarter larger.)
double Lookahead::dense_epsilon(std::size_t i) const {
    const Segment& s = seg(i);
    return std::isfinite(s.tolerance) || i == 0 || entry_is_stop(i) ? s.tolerance : seg(i - 1).tolerance;
}

// A run that a stop asked for ends one block beyond block i: before it (the block before i starts
// after one) or after it (the block after i ends in G61). Block i is then not dense merely for
// lying between smooth corners: held at one speed, a 25 mm block crawled at the speed at which
// the next 0.86 mm block could stop (firtp_cliffs seed 1 program 127: 1.309 -> 1.488 s with the
// velocity limits a quarter higher, which made it short). The estimates decide, as at a stop.
bool Lookahead::run_ends_next(std::size_t i) const {
    return (i >= 2 && seg(i - 2).kind == Kind::stop && stops_whatever_follows(seg(i - 2))) || (i + 1 < count_ && seg(i + 1).exact_stop);
}

void Lookahead::classify(std::size_t i) {
    Segment& s = seg(i);
    if (i == 0 && frozen_.moving) return;  // under way: it stays what it was planned as
    // A long neighbour slower than this block is not smooth either: the junction is a corner at
    // one speed on both sides, and a block held at one speed would keep the neighbour's.
    const bool entry_smooth = i == 0 || seg(i - 1).kind == Kind::stop || (smooth(i - 1) && !slower_long(i - 1, i));
    const bool exit_smooth = i + 1 == count_ || s.kind == Kind::stop || (smooth(i) && !slower_long(i + 1, i));
    // Dense: inside one dense kernel at its feed (several blocks share a window); a longer block
    // held at one speed would crawl through its whole length behind a slow junction.
    // (Judged in the stage of every axis: in its own, narrower, a block leaves the window for the
    // sparse class, whose T2 is every axis' too: firtp_cliffs seed 7 program 160, 2.5x slower.)
    const Regime wide = dense_regime(dense_epsilon(i), AxisVector::Ones());
    const bool in_window = s.length < s.feed_max * (wide.t2 + s.feed_max * box(s.u, wide));
    // Between two stops a sized start and stop are the fastest plan there is, the jerk-limited
    // rest-to-rest move. (At the end of the blocks known so far too: the next block classifies it
    // again, and a start waits for the junction after its block to be settled.)
    const bool alone = sized_ && entry_is_stop(i) && exit_is_stop(i);
    // Between two smooth corners a short block is dense unless its sparse estimate is faster: a
    // tie (both at its feed) goes dense, a run goes on through it. (Dense there whatever the
    // estimates, a 1.54 mm block after one of 0.02 mm ran at 6.4 mm/s where sparse it reached
    // 43: firtp_cliffs seed 31 program 61, +15 % with every tolerance a quarter larger. A tie
    // taken sparse slowed polygon360.ngc at jerk 5e6 from 0.564 to 0.909 s.) Next to a stop it is
    // the run's end, and the estimates decide a tie too (taken as dense there, a block ending at
    // a stop kept its entry corner's speed over its whole length: firtp_cliffs seed 3 program 24,
    // +46 % with every tolerance a quarter larger; seed 5 program 22 took 1.795 s, now 0.230 s).
    const bool inside = !entry_is_stop(i) && !exit_is_stop(i);
    // A block beside a stop that pays (stop_pays) stays sparse: dense, that junction became a corner
    // again, at a speed its dense estimate had not seen (firtp_cliffs seed 7 program 9: 4.8 mm at
    // 0.41 mm/s, 12.05 s instead of 0.63).
    const auto pays = [this](const Segment& j) { return j.kind == Kind::stop && stop_bound(j) == CornerBound::stop_pays; };
    const bool paid_stop = (i > 0 && pays(seg(i - 1))) || pays(s);
    s.dense = false;
    if (s.short_block && in_window && !s.sparse_only && !alone && !paid_stop) {
        const double dense_v = dense_estimate(i), sparse_v = sparse_estimate(i);
        s.dense = dense_v > sparse_v || (dense_v == sparse_v && inside && entry_smooth && exit_smooth && !run_ends_next(i));
    }
    s.narrowed = false;
    if (s.dense) return void(smooth_dense(i));
    set_regime(s, s.own);
}

// The tolerance a dense block's regime keeps (classify decides its class at dense_epsilon's):
// where the run of dense blocks it lies in starts from rest or ends in a stop, no more than that
// run is long. Next to a stop so short a run is slow, bound by its room or the stop, and a regime
// sized by a tolerance it cannot use only lengthens its start or stop and the ramps beside it,
// which share its stage T2_d = 2 cbrt(3 eps / J): firtp_cliffs seed 99 program 263, a 0.05 mm
// dense block from rest at 0.95 mm, took 0.0945 -> 0.1005 s with every tolerance a quarter larger
// (T2_d 75 -> 81 ms), now 0.064 s both. Between smooth corners the run keeps the whole: there the
// tolerance bounds the corner it makes (a 0.0001 mm arc between two 1 mm lines of
// ugs__Gates_combined_R12.nc, its line 1332, slowed the line before it 45 % at its length). So
// does a run of more than run_walk blocks. A run that goes on to the newest block ends at the
// window's stop till the next block comes, and the program's last at its end (firtp_cliffs seed 99
// program 105, a last block of 0.04 mm: 0.338 -> 0.359 s with the accelerations a quarter higher,
// now 0.314 s); its blocks are decided again as it grows (resmooth_run: never decided again, the
// first blocks of a 360-gon of radius 2 mm from rest kept the few they saw, 0.262 -> 0.561 s).
// A run in line (no junction in it or at its ends turns) uses the tolerance at no corner: its
// start and its stop alone take the stage, half the run each, and it keeps no more than half its
// length (firtp_cliffs seed 31 program 152, 0.090 and 0.226 mm in line from rest to the end at
// 0.57 and 0.21 mm: 0.114 s, 0.116 s a quarter looser; now 0.1065 s both. At a quarter of its
// length some such runs took 3 % longer).
double Lookahead::run_epsilon(std::size_t i) const {
    const double epsilon = dense_epsilon(i);
    double length = seg(i).length;
    std::size_t first = i, last = i, walked = 0;
    bool straight = true;  // no junction in the run turns (so far); in line it may keep half its length
    auto short_yet = [&] { return length < (straight ? 2.0 : 1.0) * epsilon; };
    while (short_yet() && first > 0 && !entry_is_stop(first) && seg(first - 1).dense) {  // (0: under way)
        if (++walked > run_walk) return epsilon;
        length += seg(--first).length;
        straight = straight && seg(first).turn.beta < straight_angle;
    }
    while (short_yet()) {
        if (last + 1 == count_) break;  // the window's end stops it: decided again when the next comes (resmooth_run)
        if (exit_is_stop(last) || !seg(last + 1).dense) break;
        if (++walked > run_walk) return epsilon;
        straight = straight && seg(last).turn.beta < straight_angle;
        length += seg(++last).length;
    }
    const bool in_stop = entry_is_stop(first), out_stop = exit_is_stop(last);
    if (!in_stop && !out_stop) return epsilon;
    const bool in_line = straight && (in_stop || seg(first - 1).turn.beta < straight_angle) && (out_stop || seg(last).turn.beta < straight_angle);
    return std::min(epsilon, in_line ? 0.5 * length : length);
}

bool Lookahead::smooth_dense(std::size_t i, bool only_wider) {
    Segment& s = seg(i);
    const double epsilon = run_epsilon(i);
    const Regime regime = dense_regime(epsilon, s.u);
    if (only_wider && !(regime.t2 > s.regime.t2)) return false;
    s.narrowed = epsilon < dense_epsilon(i);
    set_regime(s, regime);
    return true;
}

// The dense run before block i: its end moved with the junction after i (run_epsilon: the window's
// end stops a run that reaches it), so its narrowed blocks are decided again, and where the run
// grew, they and the junctions beside them keep more tolerance now (bounds_joined goes down to
// regime_change_). Not decided again, the blocks before the newest had to keep the whole
// tolerance: two of 0.023 and 0.010 mm from rest at 0.10 mm took 0.061 s, and 0.065 s a quarter
// looser; now 0.048 s both (firtp_cliffs seed 5 program 104). Never narrower: where a block beside
// turned sparse, a sparse block between a narrowed run and a whole one took two ramp stages and
// fitted 6 of its 14 mm/s (seed 31 program 229: +14.5 % a quarter looser).
void Lookahead::resmooth_run(std::size_t i) {
    if (!seg(i).dense) return;  // (the run before ends at i - 1: it may only have shrunk)
    for (std::size_t k = i, walked = 0; k > 0 && walked <= run_walk; ++walked) {
        if (entry_is_stop(k) || !seg(--k).dense || (k == 0 && frozen_.moving)) return;
        if (!seg(k).narrowed || !smooth_dense(k, true)) continue;
        junction_caps(k);
        if (k > 0) junction_caps(k - 1);
        regime_change_ = std::min(regime_change_, k > 0 ? k - 1 : 0);
    }
}

void Lookahead::junction_caps(std::size_t i) {
    // The ramps beside the junction change with it: their segments are planned again.
    const Regime out = seg(i).out_ramp, in = seg(i + 1).in_ramp;
    set_junction(i);
    if (seg(i).out_ramp != out) ramp_change_ = std::min(ramp_change_, i);
    else if (seg(i + 1).in_ramp != in) ramp_change_ = std::min(ramp_change_, i + 1);
}

void Lookahead::set_junction(std::size_t i) {
    Segment& s = seg(i);
    const Segment& n = seg(i + 1);
    s.out_ramp = seg(i + 1).in_ramp = Regime{-1.0};
    if (stops_whatever_follows(s)) return set_stop(i, CornerBound::stop);
    s.kind = s.dense && n.dense ? Kind::dense : Kind::corner;
    s.junction = s.dense || n.dense ? junction_regime(s.dense, s.regime, n.dense, n.regime) : corner_regime(s, n);
    s.turn_alpha = box(s.turn.du, s.junction);
    s.corner_cap = infinity;
    s.cap_bound = CornerBound::feed;
    bool tight_corner = false;
    if (s.turn.beta >= straight_angle && std::isfinite(s.tolerance)) {
        double epsilon = s.tolerance;
        if (parameters_.tolerance_meaning == ToleranceMeaning::contour) epsilon /= std::cos(0.5 * s.turn.beta);
        s.corner_cap = sampled_speed(s.turn_alpha, s.junction.t2, s.turn.s, s.turn.du.norm(), epsilon * (1.0 - plan_margin));
        s.cap_bound = CornerBound::tolerance;
        // Between sparse blocks the corner may take its tolerance's regime (a tight tolerance on a
        // machine with a long T2), the ramps beside it sharing it, where that pays (tight_pays).
        if (s.junction.sparse && !s.dense && !n.dense && s.corner_cap < std::max(s.feed_max, n.feed_max)) {
            const Regime tight = dense_regime(s.tolerance, s.u.cwiseAbs() + seg(i + 1).u.cwiseAbs());
            const double alpha = box(s.turn.du, tight);
            const double cap = sampled_speed(alpha, tight.t2, s.turn.s, s.turn.du.norm(), epsilon * (1.0 - plan_margin));
            if (tight_pays(i, tight, alpha, cap, s.junction, s.turn_alpha, s.corner_cap))
                s.junction = tight, s.turn_alpha = alpha, s.corner_cap = cap, tight_corner = true;
        }
    }
    // Between sparse blocks a stop may be faster (lookahead_stop.cpp): by estimate here, planned
    // once the blend is set.
    const bool weigh = s.kind == Kind::corner && std::isfinite(s.corner_cap) && sized(i) && sized(i + 1) && !s.dense && !n.dense;
    if (weigh && stop_pays(i, s.corner_cap)) return set_stop(i, CornerBound::stop_pays);
    if (s.kind == Kind::corner)  // a dense neighbour hosts half the corner's box in its one leg
        for (std::size_t k : {i, i + 1})
            if (seg(k).dense) {
                const double room = room_cap(k, s.turn_alpha);
                if (room < s.corner_cap) s.corner_cap = room, s.cap_bound = CornerBound::room;
            }
    if (!(s.corner_cap > 0.0)) return set_stop(i, CornerBound::stop);  // no speed passes it (corner_cap is read of corners only)
    // A corner in a dense run's regime: the ramps beside it on a sparse block share its jerk stage,
    // their boxes up to J T2 (a box alone at that height keeps the jerk at J; where an axis swings
    // the other way within T2 the exact check finds it, and they keep the run's caps: replan).
    if (s.kind == Kind::corner && !s.junction.sparse) {
        // (A tight corner's ramps keep its own caps: at J T2 they swung past the jerk limit and the
        // checks lowered the corners, firtp_bench's random corners 19 % slower.)
        const Regime ramp = s.ramps_capped && !tight_corner ? ramp_sharing(s.junction) : s.junction;
        // (Beside a run narrowed at a stop, run_epsilon, a ramp whose own stage is longer keeps its
        // own: shared, its box of at most J T2 slowed a 50.9 mm block after a 0.018 mm one from
        // rest, firtp_cliffs seed 2 program 82, 0.617 -> 0.687 s; now 0.576 s.)
        const bool narrowed = s.dense ? s.narrowed : n.narrowed;
        if (!s.dense && !(narrowed && ramp.t2 < s.regime.t2)) s.out_ramp = ramp;
        if (!n.dense && !(narrowed && ramp.t2 < n.regime.t2)) seg(i + 1).in_ramp = ramp;
    }
    // A sparse corner's stage longer than a block's own (own_regime): the ramp beside it on
    // that block takes it with its own boxes (their jerk only falls), so the two share a moving
    // average instead of keeping their kernels apart (profile.hpp).
    if (s.kind == Kind::corner && s.junction.sparse) {
        if (!s.dense && s.junction.t2 > s.regime.t2) s.out_ramp = stretched(s.regime, s.junction.t2);
        if (!n.dense && s.junction.t2 > n.regime.t2) seg(i + 1).in_ramp = stretched(n.regime, s.junction.t2);
    }
    set_overlap(i);
    if (weigh) stop_if_faster(i);
}

// Overlap where it is safe at every speed the corner may take, up to V_max = the blocks' feeds at
// 100 % (above, an overlap long enough to pay would break the tolerance: the corner is held to
// V_max at a higher override), and costs nothing else:
//   - a turn of 120 degrees or more: the leg across it, V (u + u'), is no faster than V (nor, at
//     V_max, than an axis' velocity limit);
//   - both blocks sparse and the corner in the machine's regime, passed at V_max as one step (the
//     tolerance does not bound it); the corner tolerance, not the contour one (the legs would
//     stand in for the programmed path there);
//   - the steps' boxes apart by the spacing rules at V_max (Tk only grows as V falls, the boxes
//     shrink), and the corner error within the tolerance at V_max, measured at the middle of the
//     leg across the corner (an upper bound of the closest approach; s overlap once both kernels
//     have passed there, Eq. 13/14's limit);
//   - each block keeps a leg at V_max as long as those widths after giving up overlap at both ends.
void Lookahead::set_overlap(std::size_t i) {
    Segment& s = seg(i);
    const Segment& n = seg(i + 1);
    s.overlap = 0.0;
    if (s.kind != Kind::corner || s.no_overlap || !s.junction.sparse || s.dense || n.dense || !s.regime.sparse || !n.regime.sparse ||
        parameters_.tolerance_meaning != ToleranceMeaning::corner_point || !std::isfinite(s.tolerance) || !(s.turn.s > 0.0))
        return;
    const AxisVector across = s.u + n.u;
    if (across.squaredNorm() > 1.0) return;  // a turn of less than 120 degrees
    const double v = std::min(s.feed, n.feed);
    if (!(v > 0.0) || s.corner_cap < v || s.learned_cap < v) return;
    if (across.norm() > 0.0 && velocity_cap(limits_, unit(across)) < v * across.norm()) return;
    const Step rise = make_step(v * n.u, s.junction), fall = make_step(-v * s.u, s.junction);
    const double peak = v / std::max(rise.box, rise.t2) + v / std::max(fall.box, fall.t2);  // both steps' at once
    const double epsilon = s.tolerance * (1.0 - plan_margin) - chord_margin(peak, jerk_norm_, parameters_.period);
    // At the middle of the leg across the corner, Tk / 2 from both steps, each pulse has moved
    // R(Td / 2 + Tk / 2) = Tk / 2 + lead_at(Tk / 2) of the way past it: the tool is there
    // V (u' f_rise - u f_fall) from the corner point. That grows with the overlap, and with V at
    // a given overlap (the kernels widen, Tk shrinks): an overlap that passes at V_max passes below.
    auto error = [&](double overlap) {
        const double half = 0.5 * overlap / v;
        return v * (n.u * (half + rise.kernel.lead_at(half)) - s.u * (half + fall.kernel.lead_at(half))).norm();
    };
    const double gap = rules_.spacing(rise.shape(), fall.shape());  // Tk at least
    double lo = v * gap, hi = epsilon / s.turn.s;  // error >= s overlap
    if (!(lo > 0.0) || !(hi >= lo) || error(lo) > epsilon) return;
    if (error(hi) > epsilon)  // the kernels still move at the middle: bisect (the error has no closed inverse there)
        for (int k = 0; k < 48 && hi - lo > 1e-12 * hi; ++k) (error(0.5 * (lo + hi)) <= epsilon ? lo : hi) = 0.5 * (lo + hi);
    else
        lo = hi;
    const double overlap = lo;
    const double widths = std::max(rise.kernel.width(), fall.kernel.width());
    for (double length : {legs_length(i, 0.0, 0.0), n.length})
        if (overlap > length / 3.0 || length - 2.0 * overlap < v * widths) return;
    // A hold that comes as the first step starts waits for the second, then brakes: within
    // hold_time_bound() if Tk + 2.5 (V alpha + T2) is (both steps' kernels and a stop from V, the
    // widest at V_max). Slower, the overlap shrinks to V Tk_max.
    const double tk_max = hold_bound_ - 2.5 * widths - 2.0 * parameters_.period;
    if (!(tk_max >= gap)) return;  // (below overlap / V_max: a shorter Tk at V_max)
    s.overlap = overlap;
    s.overlap_tk = tk_max;
    if (s.corner_cap > v) s.corner_cap = v, s.cap_bound = CornerBound::tolerance;
}

Lookahead::Regime Lookahead::ramp_sharing(const Regime& corner) const {
    Regime ramp = corner;
    for (int a = 0; a < limits_.axes; ++a)
        if (std::isfinite(ramp.cap[a]) && limits_.axis[a].max_jerk > 0.0)
            ramp.cap[a] = std::min(limits_.axis[a].max_acceleration, limits_.axis[a].max_jerk * ramp.t2);
    return ramp;
}

Lookahead::Regime Lookahead::ramp_on_block(std::size_t i, const Regime& ramp) const {
    const Segment& s = seg(i);
    if (!shares(s.in_ramp) || !shares(s.out_ramp)) return ramp;
    Regime r = ramp;
    for (int a = 0; a < limits_.axes; ++a)
        if (std::isfinite(r.cap[a]) && limits_.axis[a].max_jerk > 0.0) r.cap[a] = std::min(r.cap[a], 0.5 * limits_.axis[a].max_jerk * r.t2);
    return r;
}

void Lookahead::set_turn(Segment& s, const AxisVector& next_u) const {
    s.turn = make_turn(s.u, next_u, limits_);
    s.turn_box = rules_.unit_box(s.turn.direction);
}

void Lookahead::link(std::size_t i) {
    Segment& s = seg(i);
    // Kept sparse as the newest (class_if_faster): back as the estimates left it before it is
    // classed again. Its corner a blend first: smooth_dense reads it (a G61 block's tolerance is
    // its entry corner's, dense_epsilon).
    if (std::exchange(s.sparse_as_newest, false) && i > 0) {
        s.dense = true;
        junction_caps(i - 1);
        smooth_dense(i);
        junction_caps(i - 1);
    }
    set_turn(s, seg(i + 1).u);
    s.learned_cap = infinity;  // (what the checks learned at its old end)
    s.no_overlap = false;
    s.ramps_capped = true;
    s.one_speed_start = false;
    s.kind = stops_whatever_follows(s) || seg(i + 1).dwell > 0.0
                 ? Kind::stop
                 : Kind::corner;
    s.sparse_cap = s.tight_cap = 0.0;
    if (s.kind != Kind::stop) {
        s.sparse_cap = s.tight_cap = infinity;
        if (s.turn.beta >= straight_angle && std::isfinite(s.tolerance)) {
            const Segment& n = seg(i + 1);
            const AxisVector either = s.u.cwiseAbs() + n.u.cwiseAbs();
            const Regime machine = corner_regime(s, n);
            s.sparse_cap = s.tight_cap = corner_speed(s.turn.alpha, machine.t2, s.turn.s, s.tolerance);
            if ((s.short_block || n.short_block) && s.sparse_cap < std::max(s.feed_max, n.feed_max)) {  // (sparse_estimate's)
                const Regime tight = dense_regime(s.tolerance, either);
                const double alpha = box(s.turn.du, tight);
                const double cap = corner_speed(alpha, tight.t2, s.turn.s, s.tolerance);
                if (tight_pays(i, tight, alpha, cap, machine, s.turn.alpha, s.sparse_cap)) s.tight_cap = cap;
            }
        }
    }
    // Whether the blocks on either side are dense depends on this junction: they and the
    // junctions next to them are decided again.
    classify(i);
    classify(i + 1);
    // (Block i's run ends where block i + 1 is not dense: known only now.)
    if (seg(i).dense && !(i == 0 && frozen_.moving)) smooth_dense(i);
    resmooth_run(i);
    // The newest junction first: the one before weighs its stop with the plan of the block after
    // it, whose exit is this junction (lookahead_stop.cpp).
    junction_caps(i);
    class_if_faster(i);
    if (i > 0) junction_caps(i - 1);
}

// ---- The profile of one segment ----------------------------------------------------------------

Lookahead::Fitting::Fitting(const Lookahead& lookahead, std::size_t i) : la_(lookahead), i_(i) {
    const Segment& s = la_.seg(i);
    in_.length = la_.legs_length(i, 0.0, 0.0);  // (input() takes the overlaps off at the speeds)
    in_.alpha = s.alpha;
    in_.t2 = s.regime.sparse ? s.regime.t2 : la_.rules_.t2;
    const Regime in_ramp = la_.in_ramp_regime(i), out_ramp = la_.out_ramp_regime(i);
    if (in_ramp != s.regime) in_.in_t2 = in_ramp.t2, in_.in_alpha = la_.box(s.u, in_ramp), in_.in_gapped = in_ramp.sparse;
    if (out_ramp != s.regime) in_.out_t2 = out_ramp.t2, in_.out_alpha = la_.box(s.u, out_ramp), in_.out_gapped = out_ramp.sparse;
    in_.u = s.u;
    in_.u_unit_box = s.u_box;
    const bool moving = i == 0 && la_.frozen_.moving;
    // The entry step: the frozen one (fixed), one whose box scales with the speed (entry_shape at
    // speed 1), or a dense junction (speed and turn at once: entry_shape() at each speed).
    if (moving) {
        in_.in = la_.frozen_.step.shape();
        entry_fixed_ = true;
    } else if (la_.entry_scales(i)) {
        in_.in = la_.entry_shape(i, 1.0);
        entry_scaled_ = true, in_scale_ = in_.in.box;
    }
    // The exit step: a stop or a junction, box = b * its box at speed 1.
    in_.out = la_.exit_shape(i, 1.0);
    out_scale_ = in_.out.box;
    out_sized_ = la_.exit_is_stop(i) && la_.sized(i);
    // Across a sparse corner the ramps on either side may swing an axis the other way: keep T2
    // between their boxes, half on each side, where the corner's own box does not.
    corner_in_ = i == 0 ? la_.frozen_.moving && la_.frozen_.junction : !la_.entry_is_stop(i);
    corner_out_ = !la_.exit_is_stop(i);
    if (moving) in_.entry_elapsed = -la_.frozen_centre();
    if (entry_fixed_ || entry_scaled_) in_.gaps = &gaps_;  // a dense entry turns with the speed
}

const ProfileInput& Lookahead::Fitting::input(double a, double b) {
    in_.length = la_.legs_length(i_, a, b);
    if (entry_scaled_) in_.in.box = a * in_scale_;
    else if (!entry_fixed_) in_.in = la_.entry_shape(i_, a);
    if (out_sized_) la_.resize_sized(i_, b, in_.out);  // (its direction and unit box stay)
    else in_.out.box = b * out_scale_;
    // (The stage of the ramps beside each end: the block's own, or a sparse corner's they share.)
    const double t2_in = in_.in_gapped ? in_.in_t2 : in_.t2, t2_out = in_.out_gapped ? in_.out_t2 : in_.t2;
    in_.in_reserve = corner_in_ && in_.in.t2 == t2_in ? 0.5 * std::max(0.0, t2_in - in_.in.box) : 0.0;
    in_.out_reserve = corner_out_ && in_.out.t2 == t2_out ? 0.5 * std::max(0.0, t2_out - in_.out.box) : 0.0;
    return in_;
}

Lookahead::MemoKey Lookahead::Fitting::key() const {
    const int axes = la_.limits_.axes;
    MemoKey key;
    key.size = 0;
    auto put = [&](double v) { key.put(v); };
    auto put_vector = [&](const AxisVector& v) {
        for (int k = 0; k < axes; ++k) put(v[k]);
    };
    put(in_.t2);
    put(la_.legs_length(i_, 0.0, 0.0)), put(in_.alpha), put(in_.u_unit_box), put_vector(in_.u);
    const bool in_overlap = i_ > 0 && la_.overlapped(i_ - 1), out_overlap = la_.overlapped(i_);  // (legs_length's)
    put(in_overlap ? la_.seg(i_ - 1).overlap : 0.0), put(in_overlap ? la_.seg(i_ - 1).overlap_tk : 0.0);
    put(out_overlap ? la_.seg(i_).overlap : 0.0), put(out_overlap ? la_.seg(i_).overlap_tk : 0.0);
    put(in_.in_t2), put(in_.in_alpha), put(in_.out_t2), put(in_.out_alpha), put(in_.in_gapped + 2.0 * in_.out_gapped);
    put(in_.entry_elapsed);
    put((entry_fixed_ ? 1 : 0) + (entry_scaled_ ? 2 : 0) + (corner_in_ ? 4 : 0) + (corner_out_ ? 8 : 0) + (out_sized_ ? 16 : 0));
    if (entry_fixed_ || entry_scaled_) {
        put(entry_scaled_ ? in_scale_ : in_.in.box), put(in_.in.t2), put(in_.in.unit_box), put_vector(in_.in.direction);
    } else if (la_.entry_is_stop(i_)) {  // a sized start: entry_shape() at each speed
        put(la_.seg(i_).alpha), put(la_.seg(i_).u_jerk);
    } else {  // a dense junction: entry_shape() from the block before at each speed
        const Segment& prev = la_.seg(i_ - 1);
        put(prev.b), put_vector(prev.u), put(prev.junction.t2), put_vector(prev.junction.cap);
    }
    put(out_scale_), put(in_.out.t2), put(in_.out.unit_box), put_vector(in_.out.direction);
    return key;
}

ProfileInput Lookahead::profile_input(std::size_t i, double a, double b) const {
    ProfileInput in = Fitting(*this, i).input(a, b);
    in.gaps = nullptr;  // the Fitting's, gone
    return in;
}

bool Lookahead::fits(std::size_t i, double a, double p, double b) const { return Fitting(*this, i)(a, p, b); }

// Both segments dense, one speed each (b before, a after): the junction step dV = a u' - b u,
// its box within each leg (tile), and the corner within its tolerance by estimate: the step's
// pull towards the inside of the turn, and the run's jerk stage smoothing the curve the steps
// trace (a T2 moving average of a parabola: a T2^2 / 24). The check measures it exactly.
Lookahead::DenseJunction Lookahead::dense_junction(std::size_t i) const {
    DenseJunction j;
    j.i = i;
    j.s = &seg(i);
    j.n = &seg(i + 1);
    j.length = seg_length(i);
    if (i == 0 && frozen_.moving) {
        j.width_fixed = true;
        j.width_add = frozen_.step.kernel.width();
    } else if (entry_scales(i)) {
        const StepShape unit = entry_shape(i, 1.0);
        j.width_scale = unit.box, j.width_add = unit.t2;
    } else {
        j.dense_before = &seg(i - 1);
        j.width_add = j.dense_before->junction.t2;
    }
    j.bounded = !(j.s->turn.beta < straight_angle || !std::isfinite(j.s->tolerance));
    if (j.bounded) {
        j.m = unit(j.s->u + j.n->u);
        j.epsilon = j.s->tolerance;
        if (parameters_.tolerance_meaning == ToleranceMeaning::contour) j.epsilon /= std::cos(0.5 * j.s->turn.beta);
    }
    return j;
}

Probe Lookahead::dense_probe(const DenseJunction& j, double b, double a) const {
    const std::size_t i = j.i;
    const Segment& s = *j.s;
    const Segment& n = *j.n;
    // The margin: the least relative slack of the conditions tested (a search's guide only).
    double margin = 1.0;
    auto slack = [&margin](double room, double need) {
        if (std::isfinite(room) && std::isfinite(need))
            margin = std::min(margin, (room - need) / std::max({std::abs(room), std::abs(need), 1e-300}));
    };
    slack(s.learned_cap, std::max(a, b));
    if (std::max(a, b) > s.learned_cap) return {false, margin};
    const AxisVector dv = a * n.u - b * s.u;
    const double t1 = box(dv, s.junction);
    const double leg_s = b > 0.0 ? j.length / b : infinity, leg_n = a > 0.0 ? n.length / a : infinity;
    slack(leg_s, t1), slack(leg_n, t1);
    if (t1 > leg_s || t1 > leg_n) return {false, margin};
    // Kernels start in the steps' order: a step wider than the one entering the block waits.
    const double entry_width = j.width_fixed ? j.width_add
                               : j.dense_before != nullptr
                                   ? box(b * s.u - j.dense_before->b * j.dense_before->u, j.dense_before->junction) + j.width_add
                                   : b * j.width_scale + j.width_add;
    slack(leg_s, 0.5 * (t1 + s.junction.t2 - entry_width));
    if (leg_s < 0.5 * (t1 + s.junction.t2 - entry_width)) return {false, margin};
    // ... and not before now (a hold brakes in the block under way).
    if (i == 0 && frozen_.moving) {
        slack(frozen_centre() + leg_s, 0.5 * (t1 + s.junction.t2));
        if (frozen_centre() + leg_s < 0.5 * (t1 + s.junction.t2)) return {false, margin};
    }
    if (!j.bounded) return {true, margin};
    const AxisVector& m = j.m;
    const double inward = (dv - m * dv.dot(m)).norm();
    const double t2 = s.junction.t2;
    double estimate = inward * two_stage(t1, t2).lead();
    const double legs = 0.5 * (std::isfinite(leg_s) ? leg_s : 0.0) + 0.5 * (std::isfinite(leg_n) ? leg_n : 0.0);
    if (legs > 0.0) estimate += inward / legs * t2 * t2 / 24.0;
    estimate += chord_margin(t1 > 0.0 ? dv.norm() / std::max(t1, t2) : 0.0, jerk_norm_, parameters_.period);
    slack(j.epsilon, estimate);
    return {estimate <= j.epsilon, margin};
}

double Lookahead::dense_exit_max(std::size_t i, double next_entry_max) const {
    const DenseJunction j = dense_junction(i);
    auto probe = [&](double b) { return dense_probe(j, b, std::min(b, next_entry_max)); };
    const Segment& s = seg(i);
    // Braking along a dense run, the legs (or a learned cap) bound it: where they flip is the
    // search's guess (pcb2gcode back: 98 % of these searches, 4.3 tests each instead of 15.4).
    const auto legs = dense_leg_flip({s.u, j.n->u, s.junction.cap, limits_.axes, j.length, j.n->length}, next_entry_max);
    const double guess = legs ? std::min(*legs, s.learned_cap) : s.feed_max;
    if (guess < s.feed_max) return search::highest_near(probe, 0.0, s.feed_max, guess);
    return highest(probe, 0.0, s.feed_max);
}

double Lookahead::max_entry(std::size_t i, double exit_max) const {
    const Segment& s = seg(i);
    if (s.dense) {
        double v = std::min(exit_max, s.feed_max);
        if (entry_is_stop(i)) v = std::min(v, room_cap(i, s.alpha));  // its start step fits its leg
        return v;
    }
    Fitting fits(*this, i);
    EntryMemo& memo = entry_memo_[ring(i)];
    MemoKey key = fits.key();
    key.put(s.feed_max), key.put(exit_max);
    if (memo.key.same(key)) return memo.answer;
    // Most short blocks enter at most as fast as they may leave (tort: 98 % of the searches).
    const double answer = highest(
        [&](double a) {
            const double b = std::min(a, exit_max);
            return fits.probe(a, std::max(a, b), b);
        },
        0.0, s.feed_max, exit_max);
    memo.key.keep(key);
    memo.answer = answer;
    return answer;
}

// ---- Passes ------------------------------------------------------------------------------------

double Lookahead::corner_exit_cap(std::size_t i) const {
    const Segment& s = seg(i);
    return std::min({s.corner_cap, s.learned_cap, s.feed_max, seg(i + 1).feed_max});
}

// Junction i is decided again when block i + 2 comes (link(i + 1) classifies block i + 1 and
// recomputes the junction), unless it is a stop whatever comes after (an exact stop even before
// the next block comes).
bool Lookahead::settled(std::size_t i) const {
    const Segment& s = seg(i);
    return end_known() || i + 2 < count_ || s.exact_stop || (i + 1 < count_ && stops_whatever_follows(s));
}

// A bound the window's end limits may rise as blocks come; it may also fall while the junction
// after its block is not settled: that junction's regime may lengthen the block's ramp down. So a
// block entered at its feed, or faster than the corner before it passes, still waits for its exit
// junction. (Block 2 of Arrival's seed 1 program 37 entered at its feed, 49.7 mm/s, until the
// next block came and the junction after it took a 91 ms stage: 28.3 mm/s. The start before it,
// frozen at 44.19 mm/s when fed one block a period, takes 43.77 known at once.)
bool Lookahead::exit_end(std::size_t i) const {
    const Segment& s = seg(i);
    if (i + 1 == count_) return !end_known() && !s.exact_stop;  // an exact stop is its own, not the end's
    if (!settled(i)) return true;                              // its junction's regime may change
    if (s.kind == Kind::stop) return false;
    const Segment& n = seg(i + 1);
    if (s.kind == Kind::corner) return n.entry_end_limited && (n.entry_max < corner_exit_cap(i) || !settled(i + 1));
    return n.entry_end_limited;
}

bool Lookahead::refresh_end_flags(std::size_t i) {
    Segment& s = seg(i);
    const bool exit = exit_end(i);
    const bool entry = exit && (s.entry_max < s.feed_max * (1.0 - 1e-12) || !settled(i));
    const bool changed = exit != s.exit_end_limited || entry != s.entry_end_limited;
    s.exit_end_limited = exit;
    s.entry_end_limited = entry;
    return changed;
}

std::size_t Lookahead::refresh_end_flags_below(std::size_t i) {
    std::size_t lowest = i;
    for (std::size_t k = i; k-- > 0 && refresh_end_flags(k);) lowest = k;
    return lowest;
}

std::size_t Lookahead::backward(std::size_t last, std::size_t settled) {
    Backward w{last + 1, std::min(last, take_regime_change()), settled, count_};
    backward_some(w, static_cast<std::size_t>(-1));
    return w.changed;
}

bool Lookahead::backward_some(Backward& w, std::size_t most) {
    const std::size_t last = w.last, settled = w.settled;
    for (; w.next > 0 && most > 0; --most) {
        const std::size_t i = --w.next;
        Segment& s = seg(i);
        double exit_max = 0.0;
        if (exit_is_stop(i)) {
            exit_max = s.dense ? std::min(s.feed_max, room_cap(i, s.alpha)) : s.feed_max;
        } else {
            const Segment& n = seg(i + 1);
            if (s.kind == Kind::corner) exit_max = std::min(n.entry_max, corner_exit_cap(i));
            else exit_max = dense_exit_max(i, n.entry_max);
        }
        const double entry_max = max_entry(i, exit_max);
        const bool same = i < last && exit_max == s.exit_max && entry_max == s.entry_max;
        s.exit_max = exit_max;
        s.entry_max = entry_max;
        if (!refresh_end_flags(i) && same) {
            w.next = 0;
            break;
        }
        if (!same) w.changed = i;
        if (same && i <= settled) {
            // Only the end-limited flags changed, and the bounds before were found from what they
            // are now: they stand, the flags go on down alone (searching every bound again took
            // 0.5 ms an add at a quadrant of examples/polygon360.ngc, a queue of 256 blocks).
            refresh_end_flags_below(i);
            w.next = 0;
            break;
        }
    }
    return w.next == 0;
}

double Lookahead::entry_for(std::size_t i) const {
    if (i == 0) return frozen_.moving ? frozen_.speed : -1.0;
    const Segment& prev = seg(i - 1);
    if (prev.kind == Kind::stop) return -1.0;
    if (prev.kind == Kind::corner) return prev.b;
    // Dense: as fast as the junction allows, up to the bound and the feed; braking as little as
    // it must.
    const Segment& s = seg(i);
    const double b = prev.b;
    const DenseJunction j = dense_junction(i - 1);
    auto probe = [&](double a) { return dense_probe(j, b, a); };
    auto ok = [&](double a) { return probe(a).ok; };
    const double hi = std::min(s.brake ? 0.0 : target(i), s.entry_max), lo = std::min(b, s.entry_max);
    if (hi >= lo) return ok(lo) ? highest(probe, lo, hi) : lo;
    const double v = lowest(probe, hi, lo);
    // A hold brakes as hard as the junction allows: where even its bound's speed does not pass,
    // the stop falls in a later block (place_hold_stop goes on) rather than past a limit.
    if (s.brake && !ok(v) && b > v && ok(b)) return lowest(probe, v, b);
    return v;
}

void Lookahead::plan_segment(std::size_t i, double entry) {
    ++stats_.segments_planned;
    Segment& s = seg(i);
    const double length = seg_length(i);
    const double pt = s.brake ? 0.0 : target(i);
    if (s.dense) {
        // One speed: from rest, no more than the next block's feed across a corner after it.
        double v = entry >= 0.0 ? entry : std::min(s.entry_max, pt);
        if (entry < 0.0 && s.kind == Kind::corner && !seg(i + 1).brake) v = std::min(v, target(i + 1));
        if (!(v > 0.0)) v = 0.0;
        s.a = s.p = s.b = v;
        s.unfit = !(v > 0.0);
        s.x0 = v > 0.0 ? length / v : 0.0;
        s.xp = s.x1 = 0.0;
    } else {
        Fitting fitting(*this, i);
        // The same inputs as the last plan of this slot: the same plan (not under way: a hold
        // there reads the accepted speeds).
        const bool memo_ok = !(i == 0 && frozen_.moving);
        PlanMemo& memo = plan_memo_[ring(i)];
        MemoKey key = memo_ok ? fitting.key() : MemoKey{};
        if (memo_ok) {
            const bool stop = exit_is_stop(i);
            for (double x : {entry, pt, s.entry_max, s.exit_max, stop ? 0.0 : target(i + 1), stop ? 2.0 : seg(i + 1).brake ? 1.0 : 0.0,
                             s.brake ? 1.0 : 0.0, s.one_speed_start ? 1.0 : 0.0})
                key.put(x);
            if (memo.key.same(key)) {
                s.a = memo.a, s.p = memo.p, s.b = memo.b;
                s.x0 = memo.x0, s.xp = memo.xp, s.x1 = memo.x1;
                s.unfit = memo.unfit, s.ramped_on = memo.ramped_on;
                link_next_a(i);
                return;
            }
        }
        auto fits = [&](std::size_t, double a, double p, double b) { return fitting(a, p, b); };
        auto probe = [&](double a, double p, double b) { return fitting.probe(a, p, b); };
        double a = entry, p = 0.0, b = 0.0;
        // From rest the start's speed is the highest one-speed plan's. Where that is below the
        // target, the block ramps on up as it would once the start has frozen and it is planned
        // again under way (a start then plans the same whenever the next blocks come).
        // Where that ramp on failed the check, one speed, from rest and once started alike.
        const bool from_rest = a < 0.0;
        const bool starting = from_rest || (i == 0 && frozen_.moving && frozen_.start);
        const bool one_speed = starting && s.one_speed_start;
        auto ramps_on = [&](double start) { return !s.one_speed_start && start > 0.0 && start < pt * (1.0 - ramp_on_margin); };
        if (exit_is_stop(i)) {  // the stop step does the last ramp: b = p
            if (a < 0.0) {
                p = highest([&](double v) { return probe(v, v, v); }, 0.0, std::min(pt, s.entry_max));
                a = p;
                if (ramps_on(a)) p = highest([&](double v) { return probe(a, v, v); }, a, pt);
            } else if (one_speed && pt >= a && fits(i, a, a, a)) {
                p = a;
            } else if (pt >= a) {
                p = highest([&](double v) { return probe(a, v, v); }, a, pt);
            } else if (s.brake) {
                p = a;  // the stop step itself brakes: no ramp down to a standstill before it
            } else {
                p = fits(i, a, pt, pt) ? pt : lowest([&](double v) { return probe(a, v, v); }, pt, a);
            }
            b = p;
        } else {
            const double bt = std::min({s.exit_max, pt, seg(i + 1).brake ? 0.0 : target(i + 1)});
            if (a < 0.0) {
                p = highest([&](double v) { return probe(v, v, std::min(v, bt)); }, 0.0, std::min(pt, s.entry_max));
                a = p;
                b = std::min(p, bt);
            }
            if (one_speed && !from_rest && fits(i, a, a, std::min(a, bt))) {  // (from rest it is already)
                p = a;
                b = std::min(a, bt);
            } else if (!from_rest || ramps_on(a)) {
                if (fits(i, a, std::max(a, bt), bt)) b = bt;
                else if (bt > a) b = highest([&](double v) { return probe(a, v, v); }, a, bt);
                else b = lowest([&](double v) { return probe(a, a, v); }, bt, std::min(a, s.exit_max));
                const double top = std::max(a, b);
                if (pt >= top) p = highest([&](double v) { return probe(a, v, b); }, top, pt);
                // Braked to rest at its end: no crawl before it (the lowest p passing was 6e-15).
                else if (s.brake && !(b > 0.0)) p = top;
                else p = fits(i, a, pt, b) ? pt : lowest([&](double v) { return probe(a, v, b); }, pt, top);
                p = std::max(p, std::min(a, b));  // no standstill inside the block
            }
        }
        // A hold that cannot brake inside the block under way (its next step would have to start
        // in the past) keeps the block's accepted speeds and brakes from the next one on.
        if (i == 0 && frozen_.moving && s.brake && s.a == a && !fits(i, a, p, b) && fits(i, a, s.p, s.b))
            p = s.p, b = s.b;
        const ProfileLegs legs = profile_legs(rules_, fitting.input(a, b), a, p, b);
        s.unfit = !legs.fits;  // the check turns it back (its entry corner is lowered)
        s.ramped_on = starting && p > a;
        s.a = a, s.p = p, s.b = b;
        s.x0 = legs.x0, s.xp = legs.xp, s.x1 = legs.x1;
        if (memo_ok) {
            memo.key.keep(key);
            memo.a = a, memo.p = p, memo.b = b, memo.x0 = s.x0, memo.xp = s.xp, memo.x1 = s.x1;
            memo.unfit = s.unfit, memo.ramped_on = s.ramped_on;
        }
    }
    link_next_a(i);
}

void Lookahead::link_next_a(std::size_t i) {
    const Segment& s = seg(i);
    if (i > 0) {
        Segment& prev = seg(i - 1);
        prev.next_a = s.a;
        if (prev.kind == Kind::stop)  // at rest between the stop and this start
            prev.rest = rules_.spacing(exit_shape(i - 1, prev.b), entry_shape(i, s.a));
    }
}

void Lookahead::forward(std::size_t from) {
    const double period = parameters_.period;
    for (std::size_t i = from; i < count_; ++i) {
        plan_segment(i, entry_for(i));
        Segment& s = seg(i);
        s.planned_stop = exit_is_stop(i);
        if (i == 0) {
            s.enter = frozen_.moving ? static_cast<double>(frozen_.tick) * period + frozen_.offset
                                     : static_cast<double>(timeline_->now()) * period + next_step().centre;
        } else {
            Segment& prev = seg(i - 1);
            const double exit = prev.enter + prev.x0 + prev.xp + prev.x1;
            if (prev.kind == Kind::stop)  // as next_step() starts it
                prev.rest = std::max(prev.rest, start_after_stop(i, exit, stop_step(i - 1), 0.5 * entry_step(i).kernel.width()) - exit);
            s.enter = exit + (prev.kind == Kind::stop ? prev.rest : prev.overlap_time());
        }
    }
}

// ---- Adding a block ----------------------------------------------------------------------------

void Lookahead::open_batch() {
    Batch& b = batch_;
    if (b.window.size() < segments_.size()) b.window.resize(segments_.size()), b.blocks.reserve(capacity_);
    b.open = true;
    b.blocks.clear();
    for (std::size_t i = 0; i < count_; ++i) b.window[i] = seg(i);
    b.head = head_, b.count = count_, b.goal = goal_;
    b.pending_dwell = pending_dwell_, b.plan = plan_scalars(), b.finished = finished_;
}

Result Lookahead::add(const Block& block, Planning when) {
    last_add_tick_ = timeline_->now();
    if (join_.open && end_known()) finish_join();  // (the end its bounds found moves)
    if (when == Planning::now) {
        if (batch_.open) plan_batch();
    } else if (!batch_.open && deferred_ == 0 && !join_.open) {
        open_batch();
    }
    const AxisVector delta = block.target - goal_;
    const double length = delta.norm();
    if (length < min_block_length) {  // skipped; its dwell goes to the next block
        pending_dwell_ += block.dwell;
        if (batch_.open) batch_.blocks.push_back(block);
        return Result::skipped;
    }
    if (count_ + deferred_ >= capacity_) return Result::queue_full;
    if (batch_.open) batch_.blocks.push_back(block);
    Segment s;
    s.dwell = pending_dwell_ + block.dwell;
    s.added = static_cast<double>(timeline_->now()) * parameters_.period;
    pending_dwell_ = 0.0;
    s.start = goal_;
    s.end = block.target;
    s.u = delta / length;
    s.length = length;
    const double cap = velocity_cap(limits_, s.u);
    s.feed = std::min(block.feed, cap);
    s.feed_max = std::min(block.feed * max_rate_, cap);
    s.exact_stop = block.termination == Termination::exact_stop;
    s.tolerance = block.termination == Termination::blend ? block.tolerance : infinity;
    s.type = block.type;
    s.line = block.line;
    arrive(s);
    goal_ = block.target;
    finished_ = false;
    // Beyond the window's reach it waits; so does a block while a join is under way or after one
    // planned in this period (one a period), and one that comes under way to a window still
    // filling (gathered: lookahead_reach.cpp).
    bool waits = deferred_ > 0 || join_.open || (when == Planning::now && (join_.done == timeline_->now() || waits_beyond()));
    if (!waits && when == Planning::now && fills_under_way()) waits = filling_ = true;
    if (waits) {
        seg(count_ + deferred_) = s;
        ++deferred_;
        return Result::ok;
    }
    seg(count_) = s;
    join(when);
    return Result::ok;
}

void Lookahead::arrive(Segment& s) const {
    s.u_box = rules_.unit_box(s.u);
    s.u_jerk = 0.0;
    for (int a = 0; a < limits_.axes; ++a)
        if (limits_.axis[a].max_jerk > 0.0) s.u_jerk = std::max(s.u_jerk, std::abs(s.u[a]) / limits_.axis[a].max_jerk);
    s.feed_t2 = feed_stage(s);
    s.own = own_regime(s);
    set_regime(s, s.own);
    // (Short against the stage its corners take, at least its axes', not its own.)
    s.short_block = s.length < s.feed_max * (s.feed_max * s.alpha + corner_regime(s, s).t2);
    s.kind = Kind::stop;
    s.junction = s.regime;
    s.learned_cap = infinity;
}

void Lookahead::join(Planning when) {
    link_newest();
    if (when == Planning::now) plan_joined(count_ - 1);
}

void Lookahead::link_newest() {
    ++count_;
    if (count_ >= 2) link(count_ - 2);
    else classify(0);
}

std::size_t Lookahead::joined_first(std::size_t before, std::size_t lowest) {
    // (link() changed junction before - 2 on.) The block before them is planned again whatever its
    // bounds: its exit was the end of the path's stop and is a corner now.
    return std::min(lowest, before > 0 ? before - 1 : 0);
}

bool Lookahead::plan_joined(std::size_t before, bool undoable) {
    Backward bounds = bounds_joined(before);
    backward_some(bounds, static_cast<std::size_t>(-1));
    settle_end_flags();
    return replan(joined_first(before, bounds.changed), undoable);
}

void Lookahead::restore(const PlanScalars& p) {
    ramp_change_ = p.ramp_change, max_width_ = p.max_width, context_span_ = p.context_span;
    stats_.unfit = p.unfit;
    next_known_ = false;
}

void Lookahead::settle_end_flags() {
    // Junction count_ - 3 is settled now: its end-limited flags, and those they lift, follow
    // (the backward pass may have stopped before it; the bounds are the same).
    if (count_ >= 3) refresh_end_flags_below(count_ - 2);
}

}  // namespace firtp
