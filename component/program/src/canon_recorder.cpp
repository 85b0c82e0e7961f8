#include "canon_recorder.hpp"

#include "arc.hpp"
#include "move_speed.hpp"

#include <firtp/arc_chords.hpp>
#include <firtp/text_cat.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace firtp::gcode {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
// Farthest a move may go from the origin, machine units (mm, degrees): as messages::validate. Beyond,
// a coordinate is a typo or a unit mix-up, and lengths would overflow (1e200 squared is inf).
constexpr double max_coordinate = 1e6;

bool is_rotary(Eigen::Index axis) { return axis >= 3 && axis < 6; }

void rotate(double& x, double& y, double degrees) {
    const double t = degrees * std::numbers::pi / 180.0;
    const double xx = x, yy = y;
    x = xx * std::cos(t) - yy * std::sin(t);
    y = xx * std::sin(t) + yy * std::cos(t);
}

}  // namespace

CanonRecorder::CanonRecorder(const MachineConfig& machine, const AxisVector& start, ProgramSink& sink,
                             std::function<Place()> where)
    : machine_(machine), sink_(sink), where_(std::move(where)), position_(start) {
    tolerance_ = machine.default_tolerance;
    if (machine.fixed_chain()) filters_ = machine.filter_times();
}

AxisVector CanonRecorder::to_mm(const AxisVector& program) const {
    AxisVector mm = program;
    for (Eigen::Index a = 0; a < max_axes; ++a)
        if (!is_rotary(a)) mm[a] *= scale_;
    return mm;
}

AxisVector CanonRecorder::from_mm(const AxisVector& mm) const {
    AxisVector program = mm;
    for (Eigen::Index a = 0; a < max_axes; ++a)
        if (!is_rotary(a)) program[a] /= scale_;
    return program;
}

AxisVector CanonRecorder::to_machine(const AxisVector& program) const {
    AxisVector p = to_mm(program) + g92_;
    rotate(p[0], p[1], rotation_deg_);
    return p + g5x_ + tool_;
}

AxisVector CanonRecorder::program_position() const {
    AxisVector p = last_point() - tool_ - g5x_;
    rotate(p[0], p[1], -rotation_deg_);
    return from_mm(p - g92_);
}

void CanonRecorder::set_feed_rate(double program_units_per_min) {
    if (program_units_per_min != feed_written_ || program_units_per_min * scale_ != feed_) end_chain();
    feed_written_ = program_units_per_min;
    feed_ = program_units_per_min * scale_;
}

void CanonRecorder::set_blend(double program_tolerance) {
    end_chain();
    termination_ = Termination::blend;
    tolerance_ = program_tolerance > 0.0 ? program_tolerance * scale_ : machine_.default_tolerance;
}

// F in mm/s (deg/s for A B C alone); G95: F per spindle revolution at the programmed speed.
double CanonRecorder::programmed_speed(bool linear) const {
    const double per_min = linear ? feed_ : feed_written_;
    return per_rev_ ? per_min * rpm_ / 60.0 : per_min / 60.0;
}

void CanonRecorder::straight(bool rapid, int line, const AxisVector& program_target) {
    if (error_) return;
    if (!rapid) return feed_point(line, to_machine(program_target));
    end_chain();
    line_block(rapid, line, to_machine(program_target));
}

void CanonRecorder::feed_point(int line, const AxisVector& target) {
    if (termination_ != Termination::blend || !(naive_cam_ > 0.0)) {
        end_chain();
        return line_block(false, line, target);
    }
    if (!extends_chain(chain_, position_, target, naive_cam_)) end_chain();
    chain_.push_back({target, line});
    if (target.tail<6>() != position_.tail<6>()) end_chain();  // A B C U V W move alone
}

void CanonRecorder::motion_waits() {
    end_chain();
    wait_pending_ = held_.has_value();
}

void CanonRecorder::end_chain() {
    if (chain_.empty() || error_) return chain_.clear();
    const ChainPoint last = chain_.back();
    joined_.moves += chain_.size() - 1;
    joined_.farthest = std::max(joined_.farthest, chain_deviation(chain_, position_));
    chain_.clear();
    line_block(false, last.line, last.at);
}

// G0 as fast as the limits allow; G1 at F along the X Y Z length, else U V W, else A B C (deg/min).
void CanonRecorder::line_block(bool rapid, int line, const AxisVector& target) {
    const AxisVector delta = target - position_;
    const MoveLengths lengths = move_lengths(delta);
    if (!lengths.moves()) return;
    const double path = lengths.feed_length();
    const double cap = speed_cap(delta, path, lengths.linear(), machine_.limits);
    const double programmed = programmed_speed(lengths.linear());
    if (!rapid && !(programmed > 0.0))
        return fail(line, per_rev_ ? "G95 feed per revolution with the spindle speed at zero: program an S word"
                                   : "a feed move with zero feed rate: program an F word first");
    const double speed = rapid ? cap : std::min(programmed, cap);
    if (!std::isfinite(speed)) return fail(line, "G0 needs the axes' MAX_VELOCITY: this machine has no rapid speed");
    push(target, speed * (lengths.all / path), termination_, tolerance_, rapid ? MotionType::traverse : MotionType::feed,
         line);
}

void CanonRecorder::arc(int line, int plane_code, double first_end, double second_end, double first_centre,
                        double second_centre, int rotation, double normal_end, const AxisVector& program_target) {
    if (error_) return;
    const ArcPlane plane = arc_plane(plane_code);
    AxisVector end_program = program_target;
    end_program[plane.first] = first_end;
    end_program[plane.second] = second_end;
    end_program[plane.normal] = normal_end;
    AxisVector centre_program = end_program;
    centre_program[plane.first] = first_centre;
    centre_program[plane.second] = second_centre;
    const AxisVector end = to_machine(end_program);
    const AxisVector centre_point = to_machine(centre_program);
    const Eigen::Vector2d centre(centre_point[plane.first], centre_point[plane.second]);
    // A short XY arc in G64 Q joins the straight feeds collected (one turn only: LinuxCNC drops
    // the further turns of a P word there).
    if (plane_code == 170 && termination_ == Termination::blend && std::abs(rotation) == 1)
        if (const auto middle = naive_arc_middle(last_point(), end, centre, rotation > 0, naive_cam_)) {
            feed_point(line, *middle);
            return feed_point(line, end);
        }
    end_chain();
    if (rotation == 0) return line_block(false, line, end);  // LinuxCNC moves straight then

    Arc geometry;
    int uniform = 0, chords = 0;  // the tolerance's chords; those made (arc_chords.hpp)
    const bool cut_ends = !filters_;  // (the paper's fixed chain keeps equal chords)
    try {
        // LinuxCNC has checked the radii; its tolerances are in interp_internal.hh.
        geometry = make_arc(plane, position_, end, centre, rotation < 0, std::abs(rotation), ArcTolerances{0.0, infinity, infinity});
        uniform = chord_count(geometry, machine_.arc_chord_tolerance);
        chords = graded_chord_count(uniform, cut_ends);
    } catch (const ArcError& e) {
        return fail(line, e.what());
    }
    if (const std::size_t made = blocks_; static_cast<std::size_t>(chords) > machine_.max_program_blocks - made)
        return fail(line, cat(too_many_blocks(), ": this arc's ", std::to_string(chords), " chords come after ",
                              std::to_string(made), made == 1 ? " block" : " blocks",
                              " (a coarser [FIRTP]ARC_CHORD_TOLERANCE needs fewer)"));

    // Inside the arc the chords blend; in G61 / G61.1 with the machine's tolerance.
    const bool blend = termination_ == Termination::blend;
    const double inner_tolerance = blend ? tolerance_ : machine_.default_tolerance;
    // Each chord's share of the arc: the speed is the arc's, so a chord lasts its share / speed.
    auto share = [&](int k) {
        return (graded_chord_end(k, uniform, cut_ends) - graded_chord_end(k - 1, uniform, cut_ends)) * geometry.helix_length();
    };
    const double radius = std::min(geometry.start_radius, geometry.end_radius);
    double speed = programmed_speed(true);
    if (!(speed > 0.0))
        return fail(line, per_rev_ ? "G95 feed per revolution with the spindle speed at zero: program an S word"
                                   : "an arc with zero feed rate: program an F word first");
    if (filters_) speed = std::min(speed, arc_speed_limit(*filters_, radius, inner_tolerance));
    AxisVector from = position_;
    for (int k = 1; k <= chords; ++k) {
        const AxisVector to = geometry.point(graded_chord_end(k, uniform, cut_ends));
        if (move_lengths(to - from).all <= zero_length)
            return fail(line, "the arc's chords would be shorter than 1e-9 mm: raise [FIRTP]ARC_CHORD_TOLERANCE");
        speed = std::min(speed, speed_cap(to - from, share(k), true, machine_.limits));
        from = to;
    }
    from = position_;
    for (int k = 1; k <= chords && !error_; ++k) {
        const AxisVector to = geometry.point(graded_chord_end(k, uniform, cut_ends));
        const double feed = move_lengths(to - from).all * speed / share(k);  // duration = share / speed
        const bool last = k == chords;
        push(to, feed, last ? termination_ : Termination::blend, last ? tolerance_ : inner_tolerance, MotionType::feed,
             line);
        from = to;
    }
}

void CanonRecorder::push(const AxisVector& target, double feed, Termination termination, double tolerance,
                         MotionType type, int line) {
    // An arc of a huge radius can pass far beyond its end points.
    if (!(target.cwiseAbs().maxCoeff() <= max_coordinate)) return fail(line, "the move passes beyond +-1e6 machine units");
    if (!(std::isfinite(feed) && feed > 0.0)) return fail(line, "the move's speed is not a positive finite number");
    if (blocks_ >= machine_.max_program_blocks)
        return fail(line, too_many_blocks());
    for (Eigen::Index a = machine_.limits.axes; a < max_axes; ++a)
        if (std::abs(target[a] - position_[a]) > zero_length)
            return fail(line, cat("the move turns axis ", std::string(1, axis_letters[a]),
                                  " but the machine has ", std::to_string(machine_.limits.axes), " axes"));
    Block block;
    block.target = target;
    block.feed = feed;
    block.termination = termination;
    block.tolerance = termination == Termination::exact_stop ? 0.0 : tolerance;
    block.type = type;
    block.line = line;
    block.dwell = dwell_;
    dwell_ = 0.0;
    if (wait_pending_ && held_) {  // motion waited after the held block: it stops (the end stops anyway)
        held_->termination = Termination::exact_stop;
        held_->tolerance = 0.0;
    }
    wait_pending_ = false;
    release();
    held_ = block;
    ++blocks_;
    position_ = target;
}

void CanonRecorder::release() {
    if (held_) sink_.block(*held_);
    held_.reset();
    for (const ProgramEvent& e : held_events_) sink_.event(e);
    held_events_.clear();
}

void CanonRecorder::finish() {
    end_chain();
    if (error_) return;
    release();
    sink_.joined(joined_);
}

// read_gcode keeps the program whole in memory, 120 bytes a block: a few short lines of many-chord
// arcs would otherwise fill it.
std::string CanonRecorder::too_many_blocks() const {
    const std::string most = std::to_string(machine_.max_program_blocks);
    return cat("the program needs more than ", most, " blocks ([FIRTP]MAX_PROGRAM_BLOCKS = ", most, ")");
}

void CanonRecorder::spindle_speed(double rpm) {
    rpm_ = std::abs(rpm);
    event(EventKind::spindle_speed, rpm_);
}

void CanonRecorder::spindle_start(bool clockwise) {
    direction_ = clockwise ? 1 : -1;
    event(clockwise ? EventKind::spindle_clockwise : EventKind::spindle_counterclockwise, rpm_);
}

void CanonRecorder::spindle_stop() {
    if (direction_ == 0) return motion_waits();  // M5 of a stopped spindle: no event, LinuxCNC still waits
    direction_ = 0;
    event(EventKind::spindle_stop);
}

void CanonRecorder::coolant(EventKind kind) {
    if (kind == EventKind::flood_on) flood_ = true;
    if (kind == EventKind::mist_on) mist_ = true;
    if (kind == EventKind::coolant_off) {
        if (!flood_ && !mist_) return motion_waits();  // M9 calls both FLOOD_OFF and MIST_OFF: one event
        flood_ = mist_ = false;
    }
    event(kind);
}

void CanonRecorder::event(EventKind kind, double value) {
    end_chain();
    if (error_) return;
    const Place at = where_();
    if (event_waits(kind)) motion_waits();
    if (kind == EventKind::dwell) {  // a stop of that length in the timeline (Block::dwell)
        if (!(value >= 0.0 && value <= max_dwell)) return fail(at.line, cat("G4 P", std::to_string(value), ": a dwell must be 0 to ", std::to_string(static_cast<int>(max_dwell)), " s"));
        dwell_ += value;
    }
    held_events_.push_back(ProgramEvent{kind, value, blocks_, at.file, at.line});
    ++events_;
}

void CanonRecorder::refuse(const std::string& what) {
    if (!error_) fail(where_().line, cat(what, ": firtp cannot plan it"));
}

void CanonRecorder::fail(int line, const std::string& message) {
    if (!error_) error_.emplace(where_().file, line, 0, message);
}

}  // namespace firtp::gcode
