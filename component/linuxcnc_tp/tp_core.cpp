#include "tp_core.hpp"

#include <firtp/arc_chords.hpp>
#include <firtp/parameters.hpp>
#include <firtp/planner.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

namespace firtp::linuxcnc_tp {

namespace {

constexpr double cart_fuzz = 1e-8;      // LinuxCNC's CART_FUZZ: shorter X Y Z (U V W) travel does not count
constexpr double double_fuzz = 2.2204460492503131e-16;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scale(const Vec3& a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 xyz(const Pose& p) { return {p[0], p[1], p[2]}; }

bool finite(const Pose& p) {
    return std::all_of(p.begin(), p.end(), [](double v) { return std::isfinite(v); });
}

static_assert(pose_axes == max_axes, "a pose is one AxisVector");

AxisVector to_vector(const Pose& p) { return Eigen::Map<const AxisVector>(p.data()); }

Pose to_pose(const AxisVector& v) {
    Pose p;
    Eigen::Map<AxisVector>(p.data()) = v;
    return p;
}

// Lengths of the X Y Z, A B C and U V W parts of a displacement.
struct Parts {
    double xyz, abc, uvw;
};
template <class V>
Parts parts(const V& d) {
    auto len = [&](int i) { return std::sqrt(d[i] * d[i] + d[i + 1] * d[i + 1] + d[i + 2] * d[i + 2]); };
    return {len(0), len(3), len(6)};
}

// LinuxCNC's length of a move, the one its vel applies to: X Y Z when they move, else U V W, else A B C.
double feed_length(const Parts& p) {
    if (p.xyz > cart_fuzz) return p.xyz;
    if (p.uvw > cart_fuzz) return p.uvw;
    return p.abc;
}

}  // namespace

const char* describe(AddStatus status) {
    switch (status) {
        case AddStatus::ok: return "queued";
        case AddStatus::zero_length: return "zero-length move ignored";
        case AddStatus::aborting: return "the planner is aborting: move refused";
        case AddStatus::not_finite: return "a coordinate, the centre or the normal is not a finite number";
        case AddStatus::bad_feed: return "the feed (vel) must be positive and finite";
        case AddStatus::queue_full: return "the move queue is full (task ignored tcqFull)";
        case AddStatus::spindle_sync:
            return "spindle-synchronised motion (G33, G33.1, G76, G95 feed per revolution) is not supported by "
                   "firtp_tp; use the stock tpmod for it";
        case AddStatus::indexer: return "locking-indexer rotary moves are not supported by firtp_tp";
        case AddStatus::bad_arc: return "the arc has a zero radius or a zero normal";
        case AddStatus::too_many_chords: return "the arc needs too many chords: raise the module's chord_tol";
        case AddStatus::no_filters:
            return "no filter times: give t1 (and t2) to firtp_tp or set the axes' MAX_VELOCITY, MAX_ACCELERATION";
        case AddStatus::window_too_long:
            static_assert(max_window_periods == 20000.0, "the text names the bound");
            return "the filter delay T1 + ... + Tn is longer than 20000 servo periods: lower T1 (t1, else "
                   "MAX_VELOCITY / MAX_ACCELERATION) or T2 (t2, else MAX_ACCELERATION / jerk)";
    }
    return "unknown";
}

// LinuxCNC's circle (posemath pmCircleInit) for X Y Z; A B C and U V W move linearly with it.
struct Circle {
    Vec3 center{}, normal{}, rtan{}, rperp{}, rhelix{};
    double radius = 0.0, spiral = 0.0, angle = 0.0;

    // X Y Z at `fraction` of the angle (pmCirclePoint).
    Vec3 point(double fraction) const {
        const double a = fraction * angle;
        Vec3 p = add(scale(rtan, std::cos(a)), scale(rperp, std::sin(a)));
        const double r = norm(p);
        if (r > 0.0) p = add(p, scale(p, fraction * spiral / r));
        return add(add(p, scale(rhelix, fraction)), center);
    }
    double helix_length() const {
        return std::hypot(angle * (radius + 0.5 * spiral), norm(rhelix));
    }
};

struct Move {
    Pose start{}, end{};
    bool arc = false;
    Circle circle;
    int chords = 1;            // an arc's chords (arc_chords.hpp); 1 for a line
    int uniform = 1;           // ... the chord tolerance's equal-angle chords they come from
    bool cut_ends = true;      // ... the end chords cut into pieces (not with the paper's chain)
    double path_length = 0.0;  // the length vel applies to (arc: the X Y Z helix)
    double vel = 0.0, acc = 0.0;
    double speed = 0.0;        // vel with the caps, fixed when planning starts
    bool linear = true;        // X Y Z or U V W move (the velocity limit applies)
    Termination termination = Termination::blend;
    double tolerance = 0.0;        // at the move's end
    double inner_tolerance = 0.0;  // between an arc's chords
    bool atspeed = false;
    int id = 0;
    int motion_type = 0;
    unsigned char enables = 0;
    std::uint64_t blocks_end = 0;  // blocks pushed once this move was planned completely
    std::size_t tag_size = 0;
    alignas(8) unsigned char tag[tag_capacity];
};

struct OutputEvent {
    std::int64_t seq;  // applied when this move starts
    bool digital;
    int index;
    double value;
};

struct TpCore::Impl {
    TpSettings s;
    double period;
    Pose vel_limits{}, acc_limits{};
    double velocity_limit = 0.0;
    double max_rate = 1.0;       // highest feed override asked for (emcmotConfig->maxFeedScale)
    double built_rate = 1.0;     // the one the planner holds the limits for
    PlannerParameters wanted{};  // the planner the settings and the limits ask for now
    AddStatus wanted_status = AddStatus::no_filters;  // ok when it can be built
    bool dirty = true;           // the planner differs from what the settings and limits ask

    std::optional<Planner> planner;
    PlannerInput input;          // the override and pause the planner was last given (kept while aborting)
    PlannerOutput output{};      // what the planner gave at the last period: the axes, an abort's end
    Pose pose{};                 // output.state.position
    Pose goal{};                 // end of the last accepted move

    std::vector<Move> moves;     // ring, slot = seq % size
    std::int64_t next_seq = 1;   // the next accepted move's
    std::int64_t plan_seq = 1;   // first move not completely planned
    int plan_chord = 0;          // its next chord
    std::int64_t finished_seq = 0;
    std::int64_t started_seq = 0;  // newest move whose blocks started moving
    std::uint64_t pushed = 0;    // blocks queued in the planner since the last flush

    int next_id = 0;
    int term_cond = term_parabolic;
    double term_tolerance = 0.0;
    double spindle_sync = 0.0;

    std::vector<OutputEvent> events;  // ring in seq order
    std::size_t event_head = 0, event_count = 0;
    OutputWriters writers;

    bool paused = false;
    bool aborting = false;
    CycleStats stats;

    explicit Impl(const TpSettings& settings)
        : s(settings), period(settings.period), moves(settings.moves), events(256) {
        update_wanted();
        rebuild();
    }

    Move& move(std::int64_t seq) { return moves[static_cast<std::size_t>(seq) % moves.size()]; }
    const Move& move(std::int64_t seq) const { return moves[static_cast<std::size_t>(seq) % moves.size()]; }
    std::int64_t depth() const { return next_seq - 1 - finished_seq; }
    bool built() const { return planner.has_value(); }

    // The planner the settings and the limits ask for: the fixed chain when t1 is given (T2.. as
    // given, else from the limits), else smoothing at the limits.
    void update_wanted() {
        PlannerParameters p;
        p.period = period;
        p.tolerance_meaning = s.tolerance_meaning;
        p.queue_capacity = s.blocks;
        if (s.task_cycle > 0.0) p.start_idle = 3.0 * s.task_cycle + 2.0 * period;
        p.max_rate = max_rate;
        p.rate_reserve = s.rate_reserve;
        p.limits.axes = pose_axes;
        for (std::size_t a = 0; a < vel_limits.size(); ++a) {
            AxisLimits& l = p.limits.axis[a];
            l.max_velocity = std::max(vel_limits[a], 0.0);
            l.max_acceleration = std::max(acc_limits[a], 0.0);
            l.max_jerk = s.jerk_of(a);
        }
        p.fixed_chain = s.filter_times[0] > 0.0;
        if (p.fixed_chain) {
            const std::array<double, max_stages> times = limit_filter_times(p.limits, s.filter_times);
            p.filters.stages = s.stages;
            const int n = std::clamp(s.stages, 0, max_stages);
            std::copy_n(times.begin(), n, p.filters.T.begin());
            std::sort(p.filters.T.begin(), p.filters.T.begin() + n, std::greater<>());
        }
        wanted = p;
        // validate_window: a longer window would make the rebuild allocate accordingly (gigabytes
        // for a jerk limit of 1) in the servo thread; refused, counted once per change.
        bool any_acceleration = false;
        for (double acc : acc_limits) any_acceleration = any_acceleration || acc > 0.0;
        wanted_status = p.fixed_chain ? (*validate(p.filters) != '\0'                  ? AddStatus::no_filters
                                         : *validate_window(p.filters, period) != '\0' ? AddStatus::window_too_long
                                                                                         : AddStatus::ok)
                                      : any_acceleration ? AddStatus::ok : AddStatus::no_filters;
        if (wanted_status == AddStatus::window_too_long) ++stats.refused_windows;
    }

    // Only while nothing moves: the planner starts again at rest.
    void rebuild() {
        if (wanted_status != AddStatus::ok) return;  // the planner built before (if any) is kept
        const AxisVector at = output.state.position;
        planner.reset();
        wanted.max_rate = max_rate;  // the highest override asked for since the limits came
        planner.emplace(wanted, at);
        input = PlannerInput{};  // as a new planner starts
        built_rate = max_rate;
        pushed = 0;
        dirty = false;
        ++stats.rebuilds;
    }

    // Everything queued is gone; the tool rests where it is.
    void drop_moves() {
        plan_seq = next_seq;
        plan_chord = 0;
        finished_seq = next_seq - 1;
        started_seq = finished_seq;
        pushed = 0;
        event_head = event_count = 0;
        goal = to_pose(output.state.position);
        paused = false;
        aborting = false;
    }

    void rest_at(const AxisVector& at) {
        output.state.position = at;
        pose = to_pose(at);
        output.state.velocity.setZero();
        output.state.acceleration.setZero();
        output.state.jerk.setZero();
        if (built()) planner->reset(at);
        drop_moves();
    }

    // The speed fixed when a move's planning starts: vel, within the tool-tip speed limit for
    // moves of linear axes, and for the paper's chain within its arc feed cap. The axis limits the
    // planner keeps itself.
    void fix_speed(Move& m) const {
        double v = m.vel;
        if (m.linear && velocity_limit > 0.0) v = std::min(v, velocity_limit);
        if (m.arc && planner->fixed_chain())
            v = std::min(v, arc_speed_limit(planner->parameters().filters,
                                            std::min(m.circle.radius, m.circle.radius + m.circle.spiral), m.inner_tolerance));
        m.speed = v;
    }

    // The block for chord k of move m, starting at the planner's goal.
    Block chord_block(const Move& m, int k) const {
        Block b;
        const bool last = k + 1 == m.chords;
        if (m.arc && !last) {
            const double fraction = graded_chord_end(k + 1, m.uniform, m.cut_ends);
            const Vec3 p = m.circle.point(fraction);
            b.target = to_vector(m.start) + (to_vector(m.end) - to_vector(m.start)) * fraction;
            b.target.head<3>() = Eigen::Map<const Eigen::Vector3d>(p.data());  // on the arc
        } else {
            b.target = to_vector(m.end);
        }
        const double share = m.arc ? graded_chord_end(k + 1, m.uniform, m.cut_ends) - graded_chord_end(k, m.uniform, m.cut_ends) : 1.0;
        const double duration = share * m.path_length / m.speed;
        const double length = (b.target - planner->goal()).norm();
        b.feed = length > min_block_length && duration > 0.0 ? length / duration : m.speed;  // shorter: skipped
        b.termination = last ? m.termination : Termination::blend;
        b.tolerance = last ? m.tolerance : m.inner_tolerance;
        b.type = m.motion_type == motion_traverse ? MotionType::traverse : MotionType::feed;
        b.line = 0;
        return b;
    }

    std::int64_t now_ns() const { return s.clock_ns != nullptr ? s.clock_ns() : 0; }

    // Plans pending moves within the period's budget; true where the next one waits for the spindle
    // (the blocks planned then end in a rest).
    bool plan(const CycleInputs& in) {
        stats.planned = 0;
        stats.plan_ns = 0;
        if (aborting) return false;
        // Rebuilt as soon as nothing moves (not only when a move waits), so the first move of a
        // program does not wait for it.
        if ((dirty || !built()) && plan_chord == 0 && (!built() || planner->idle())) rebuild();
        if (plan_seq == next_seq || !built()) return false;
        bool spindle_wait = false;
        const bool timed = s.plan_budget_ns > 0 && s.clock_ns != nullptr;
        const std::int64_t begin = now_ns();
        while (plan_seq < next_seq && planner->free() > 0 && stats.planned < s.max_blocks_per_cycle &&
               (stats.planned == 0 || !timed || now_ns() - begin < s.plan_budget_ns)) {
            Move& m = move(plan_seq);
            if (plan_chord == 0) {
                // A spindle that must be at speed: the tool rests before the move and it waits.
                if (m.atspeed && (!planner->idle() || !in.spindle_at_speed)) {
                    spindle_wait = true;
                    break;
                }
                fix_speed(m);
            }
            Block b = chord_block(m, plan_chord);
            b.line = plan_seq;
            const Result result = planner->add(b);
            if (result != Result::ok && result != Result::skipped) {  // checked when added: cannot happen
                ++stats.refused_blocks;  // the program stops on the path
                planner->abort();
                aborting = true;
                break;
            }
            if (result == Result::ok) ++pushed;
            ++stats.planned;
            if (++plan_chord == m.chords) {
                m.blocks_end = pushed;
                ++plan_seq;
                plan_chord = 0;
            }
        }
        if (s.clock_ns != nullptr) stats.plan_ns = now_ns() - begin;
        return spindle_wait;
    }

    void apply_outputs(std::int64_t upto) {
        while (event_count > 0 && events[event_head].seq <= upto) {
            const OutputEvent& e = events[event_head];
            if (e.digital && writers.digital) writers.digital(e.index, e.value != 0.0 ? 1 : 0);
            if (!e.digital && writers.analog) writers.analog(e.index, e.value);
            event_head = (event_head + 1) % events.size();
            --event_count;
        }
    }

    void bookkeeping() {
        if (!built()) return;
        const std::uint64_t retired = planner->finished();
        while (finished_seq + 1 < plan_seq && move(finished_seq + 1).blocks_end <= retired) ++finished_seq;
        const std::int64_t line = planner->current_line();
        if (line > started_seq) started_seq = line;
        apply_outputs(std::max(started_seq, finished_seq));
        if (depth() == 0) paused = false;  // as the stock planner: an empty queue resumes
    }

    std::int64_t exec_seq() const {
        if (depth() == 0) return 0;
        return std::max(started_seq, finished_seq + 1);
    }

    bool latch(bool digital, int index, double value) {
        if (index < 0 || index >= 64 || event_count == events.size()) return false;
        events[(event_head + event_count) % events.size()] = {next_seq, digital, index, value};
        ++event_count;
        return true;
    }

    // Checks common to lines and arcs; fills the move's metadata. ok or a refusal.
    AddStatus admit(const MoveRequest& r) const {
        if (aborting) return AddStatus::aborting;
        if (!finite(r.end)) return AddStatus::not_finite;
        if (!std::isfinite(r.vel) || !(r.vel > 0.0)) return AddStatus::bad_feed;
        if (spindle_sync != 0.0) return AddStatus::spindle_sync;
        if (r.indexer_joint >= 0 || r.motion_type == motion_indexrotary) return AddStatus::indexer;
        if (depth() >= static_cast<std::int64_t>(moves.size())) return AddStatus::queue_full;
        if (wanted_status != AddStatus::ok) return wanted_status;
        return AddStatus::ok;
    }

    Move& fill(const MoveRequest& r) {
        Move& m = move(next_seq);
        m.start = goal;
        m.end = r.end;
        m.arc = false;
        m.chords = m.uniform = 1;
        m.vel = r.vel;
        m.acc = std::isfinite(r.acc) ? r.acc : 0.0;
        m.speed = r.vel;
        const bool stop = term_cond == term_stop || term_cond == term_exact;
        const double tolerance = term_tolerance > 0.0 ? term_tolerance : s.default_tolerance;
        m.termination = stop ? Termination::exact_stop : Termination::blend;
        m.tolerance = stop ? 0.0 : tolerance;
        m.inner_tolerance = tolerance;
        m.atspeed = r.atspeed;
        m.id = next_id;
        m.motion_type = r.motion_type;
        m.enables = r.enables;
        m.blocks_end = 0;
        m.tag_size = r.tag != nullptr ? std::min(r.tag_size, tag_capacity) : 0;
        if (m.tag_size > 0) std::memcpy(m.tag, r.tag, m.tag_size);
        return m;
    }

    void accept() {
        goal = move(next_seq).end;
        ++next_seq;
    }
};

TpCore::TpCore(const TpSettings& settings) {
    if (!(settings.period > 0.0)) throw std::invalid_argument("the period must be positive");
    if (settings.stages < 1 || settings.stages > max_stages) throw std::invalid_argument("stages must be 1 to 4");
    if (settings.moves < 2 * settings.full_margin + 2) throw std::invalid_argument("the move ring is too small for its margin");
    if (settings.blocks < 2) throw std::invalid_argument("the planner must hold at least 2 blocks");
    if (!(settings.default_tolerance > 0.0)) throw std::invalid_argument("the default tolerance must be positive");
    if (!(settings.chord_tolerance > 0.0)) throw std::invalid_argument("the chord tolerance must be positive");
    if (settings.max_blocks_per_cycle < 1) throw std::invalid_argument("at least one block a period must be planned");
    if (!(settings.rate_reserve > 0.0 && settings.rate_reserve < 1.0))
        throw std::invalid_argument("the rate reserve must lie between 0 and 1");
    impl_ = std::make_unique<Impl>(settings);
}

TpCore::~TpCore() = default;

bool TpCore::set_period(double seconds) {
    if (!(seconds > 0.0) || !std::isfinite(seconds)) return false;
    if (seconds != impl_->period) {
        impl_->period = seconds;
        impl_->update_wanted();  // the window's length in periods changes
        impl_->dirty = true;
    }
    return true;
}

void TpCore::set_axis_limits(const Pose& max_velocity, const Pose& max_acceleration) {
    Impl& I = *impl_;
    if (max_velocity == I.vel_limits && max_acceleration == I.acc_limits) return;
    I.vel_limits = max_velocity;
    I.acc_limits = max_acceleration;
    I.update_wanted();
    I.dirty = true;
}

void TpCore::set_velocity_limit(double limit) {
    impl_->velocity_limit = std::isfinite(limit) && limit > 0.0 ? limit : 0.0;
}

void TpCore::set_output_writers(const OutputWriters& writers) { impl_->writers = writers; }

void TpCore::set_id(int id) { impl_->next_id = id; }

bool TpCore::set_term_cond(int cond, double tolerance) {
    if (cond < term_stop || cond > term_tangent) return false;
    impl_->term_cond = cond;
    impl_->term_tolerance = std::isfinite(tolerance) && tolerance > 0.0 ? tolerance : 0.0;
    return true;
}

void TpCore::set_spindle_sync(double units_per_rev) {
    impl_->spindle_sync = std::isfinite(units_per_rev) ? units_per_rev : 1.0;
}

bool TpCore::latch_digital(int index, bool on) { return impl_->latch(true, index, on ? 1.0 : 0.0); }
bool TpCore::latch_analog(int index, double value) { return impl_->latch(false, index, value); }

AddStatus TpCore::add_line(const MoveRequest& r) {
    Impl& I = *impl_;
    if (const AddStatus why = I.admit(r); why != AddStatus::ok) return why;
    Pose d;
    for (std::size_t a = 0; a < d.size(); ++a) d[a] = r.end[a] - I.goal[a];
    const Parts p = parts(d);
    if (std::sqrt(p.xyz * p.xyz + p.abc * p.abc + p.uvw * p.uvw) < min_block_length) return AddStatus::zero_length;
    Move& m = I.fill(r);
    m.path_length = feed_length(p);
    if (!(m.path_length > 0.0)) m.path_length = std::sqrt(p.xyz * p.xyz + p.abc * p.abc + p.uvw * p.uvw);
    m.linear = p.xyz > cart_fuzz || p.uvw > cart_fuzz;
    I.accept();
    return AddStatus::ok;
}

AddStatus TpCore::add_arc(const MoveRequest& r, const ArcGeometry& g) {
    Impl& I = *impl_;
    if (const AddStatus why = I.admit(r); why != AddStatus::ok) return why;
    const bool numbers = std::all_of(g.center.begin(), g.center.end(), [](double v) { return std::isfinite(v); }) &&
                         std::all_of(g.normal.begin(), g.normal.end(), [](double v) { return std::isfinite(v); });
    if (!numbers) return AddStatus::not_finite;
    const double normal_length = norm(g.normal);
    if (!(normal_length > 0.0)) return AddStatus::bad_arc;

    // pmCircleInit: centre moved along the normal into the start's plane; turn < 0 flips the normal.
    Circle c;
    const Vec3 start = xyz(I.goal), end = xyz(r.end);
    c.normal = scale(g.normal, 1.0 / normal_length);
    const Vec3 v = sub(start, g.center);
    c.center = add(g.center, scale(c.normal, dot(v, c.normal)));
    int turn = g.turn;
    if (turn < 0) {
        turn = -1 - turn;
        c.normal = scale(c.normal, -1.0);
    }
    c.rtan = sub(start, c.center);
    c.radius = norm(c.rtan);
    if (!(c.radius > cart_fuzz)) return AddStatus::bad_arc;
    c.rperp = cross(c.normal, c.rtan);
    const Vec3 to_end = sub(end, c.center);
    c.rhelix = scale(c.normal, dot(to_end, c.normal));
    Vec3 r_end = sub(to_end, c.rhelix);
    c.spiral = norm(r_end) - c.radius;
    const double r_end_length = norm(r_end);
    r_end = r_end_length > 0.0 ? scale(r_end, c.radius / r_end_length) : scale(c.normal, double_fuzz);
    const double cosine = dot(c.rtan, r_end) / (c.radius * c.radius);
    c.angle = cosine > 1.0 ? 0.0 : cosine < -1.0 ? std::numbers::pi : std::acos(cosine);
    if (dot(cross(c.rtan, r_end), c.normal) < double_fuzz) c.angle = 2.0 * std::numbers::pi - c.angle;
    // Start and end on the same spot in the plane: a full circle.
    const Vec3 planar = sub(sub(end, start), scale(c.normal, dot(sub(end, start), c.normal)));
    if (norm(planar) < cart_fuzz) c.angle = 2.0 * std::numbers::pi;
    c.angle += 2.0 * std::numbers::pi * turn;

    const double path = c.helix_length();
    if (!(path > min_block_length)) return AddStatus::zero_length;
    // Equal-angle chords with sagitta R (1 - cos(d / 2)) <= chord_tol, at least four a turn.
    const double radius = std::max(c.radius, c.radius + c.spiral);
    const double ratio = I.s.chord_tolerance / (2.0 * radius);
    const double by_sagitta = ratio >= 1.0 ? 1.0 : std::ceil(c.angle / (4.0 * std::asin(std::sqrt(ratio))));
    const double by_turn = std::ceil(c.angle / (std::numbers::pi / 2) - 1e-9);
    const double uniform = std::max({1.0, by_sagitta, by_turn});
    const bool cut_ends = !I.wanted.fixed_chain;
    if (!(uniform <= I.s.max_chords && graded_chord_count(static_cast<int>(uniform), cut_ends) <= I.s.max_chords))
        return AddStatus::too_many_chords;

    Move& m = I.fill(r);
    m.arc = true;
    m.circle = c;
    m.uniform = static_cast<int>(uniform);
    m.cut_ends = cut_ends;
    m.chords = graded_chord_count(m.uniform, m.cut_ends);
    m.path_length = path;
    m.linear = true;
    I.accept();
    return AddStatus::ok;
}

void TpCore::pause() { impl_->paused = true; }
void TpCore::resume() { impl_->paused = false; }

void TpCore::abort() {
    Impl& I = *impl_;
    if (I.aborting) return;
    I.aborting = true;
    if (I.built()) I.planner->abort();
    // Outputs latched for moves not yet added are dropped (as the stock planner's tpClearDIOs).
    while (I.event_count > 0 && I.events[(I.event_head + I.event_count - 1) % I.events.size()].seq >= I.next_seq)
        --I.event_count;
}

void TpCore::clear() {
    Impl& I = *impl_;
    I.rest_at(I.output.state.position);
    // As the stock planner's tpClear: the latched mode goes back to plain blending, unsynchronised.
    I.term_cond = term_parabolic;
    I.term_tolerance = 0.0;
    I.spindle_sync = 0.0;
}

void TpCore::set_position(const Pose& p) {
    if (!finite(p)) return;
    impl_->rest_at(to_vector(p));
}

void TpCore::run_cycle(const CycleInputs& in) {
    Impl& I = *impl_;
    // Override above 100 %: the planner keeps the limits up to the rate it was built for.
    if (std::isfinite(in.max_feed_scale) && std::max(in.max_feed_scale, 1.0) != I.max_rate) {
        I.max_rate = std::max(in.max_feed_scale, 1.0);
        I.dirty = true;
    }
    const bool spindle_wait = I.plan(in);  // may rebuild the planner (and change built_rate): the rate is set after it
    if (I.built()) {
        const double top = std::min(std::isfinite(in.max_feed_scale) ? std::max(in.max_feed_scale, 0.0) : 1.0,
                                    I.built_rate);
        const double scale_in = std::isfinite(in.feed_scale) ? in.feed_scale : 0.0;
        if (!I.aborting) {
            I.input.rate = std::clamp(scale_in, 0.0, top);
            I.input.hold = I.paused;
            // Nothing follows the blocks planned until the spindle is at speed: they end the motion
            // for now, and a start need not wait for more.
            I.input.end_of_program = spindle_wait;
        }
        I.planner->update(I.input, I.output);
        I.pose = to_pose(I.output.state.position);
        if (I.output.flushed) I.drop_moves();  // an abort came to rest: drop the rest of the program
    } else if (I.aborting) {
        I.drop_moves();
    }
    I.bookkeeping();
    I.stats.pending = static_cast<std::size_t>(I.next_seq - I.plan_seq);
    I.stats.blocks = I.built() ? I.planner->depth() : 0;
}

const Pose& TpCore::position() const { return impl_->pose; }

bool TpCore::done() const { return impl_->depth() == 0; }
int TpCore::depth() const { return static_cast<int>(impl_->depth()); }
int TpCore::active_depth() const {
    const Impl& I = *impl_;
    return I.depth() == 0 || I.started_seq <= I.finished_seq ? 0 : static_cast<int>(I.started_seq - I.finished_seq);
}
bool TpCore::full() const {
    return impl_->depth() >= static_cast<std::int64_t>(impl_->moves.size() - impl_->s.full_margin);
}
bool TpCore::aborting() const { return impl_->aborting; }
bool TpCore::has_exec() const { return impl_->exec_seq() != 0; }
int TpCore::exec_id() const {
    const std::int64_t seq = impl_->exec_seq();
    return seq != 0 ? impl_->move(seq).id : 0;
}
int TpCore::motion_type() const {
    const std::int64_t seq = impl_->exec_seq();
    return seq != 0 ? impl_->move(seq).motion_type : 0;
}
unsigned char TpCore::exec_enables() const {
    const std::int64_t seq = impl_->exec_seq();
    return seq != 0 ? impl_->move(seq).enables : 0;
}
const void* TpCore::exec_tag() const {
    const std::int64_t seq = impl_->exec_seq();
    return seq != 0 && impl_->move(seq).tag_size > 0 ? impl_->move(seq).tag : nullptr;
}
double TpCore::current_vel() const {
    return feed_length(parts(impl_->output.state.velocity));
}
double TpCore::requested_vel() const {
    const std::int64_t seq = impl_->exec_seq();
    return seq != 0 ? impl_->move(seq).vel : 0.0;
}
double TpCore::distance_to_go() const {
    return feed_length(parts(dtg()));
}
Pose TpCore::dtg() const {
    Pose d{};
    const std::int64_t seq = impl_->exec_seq();
    if (seq == 0) return d;
    const Move& m = impl_->move(seq);
    for (std::size_t a = 0; a < d.size(); ++a) d[a] = m.end[a] - impl_->output.state.position[static_cast<int>(a)];
    return d;
}
const CycleStats& TpCore::stats() const { return impl_->stats; }
AddStatus TpCore::filter_status() const { return impl_->wanted_status; }
double TpCore::filter_delay() const { return impl_->wanted.fixed_chain ? impl_->wanted.filters.delay() : 0.0; }
const TpSettings& TpCore::settings() const { return impl_->s; }

}  // namespace firtp::linuxcnc_tp
