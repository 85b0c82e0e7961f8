#include "gcode_interpreter.hpp"

#include "arc.hpp"
#include "move_speed.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace firtp::gcode {
namespace {

constexpr double mm_per_inch = 25.4;
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::string_view axis_words = "XYZABCUVW";
constexpr std::string_view centre_letters = "IJK";  // the centre word of axis X, Y, Z
constexpr int max_turns = 10000;
// Farthest a move may go from the origin, machine units (mm, degrees): as messages::validate. Beyond,
// a coordinate is a typo or a unit mix-up, and lengths would overflow (1e200 squared is inf).
constexpr double max_coordinate = 1e6;

bool is_arc(int motion) { return motion == 20 || motion == 30; }
bool is_rotary(Eigen::Index axis) { return axis >= 3 && axis < 6; }

// "XY plane (G17)" for an arc plane.
std::string plane_name(const ArcPlane& plane) {
    switch (plane.normal) {
        case 0: return "YZ plane (G19)";
        case 1: return "XZ plane (G18)";
        default: return "XY plane (G17)";
    }
}

}  // namespace

Interpreter::Interpreter(const MachineConfig& machine, const AxisVector& start, std::vector<Block>& blocks)
    : machine_(machine), position_(start), blocks_(blocks) {
    state_.tolerance = machine.default_tolerance;
    if (machine.fixed_chain()) filters_ = machine.filter_times();  // its arcs' feed is capped
}

bool Interpreter::run(const LineWords& w, const Where& at) {
    if (const Word* f = w.get('F')) {
        if (f->value < 0.0) at.fail(f->column, cat("negative feed rate '", f->text, "'"));
        state_.feed = f->value * state_.scale;
        state_.angular_feed = f->value;
    }
    check_word_use(w, at);
    if (w.g(plane) != nullptr) state_.plane = w.code(plane);
    if (w.g(units) != nullptr) state_.scale = w.code(units) == 200 ? mm_per_inch : 1.0;
    set_control_mode(w, at);
    if (w.g(distance) != nullptr) state_.incremental = w.code(distance) == 910;
    if (w.g(arc_distance) != nullptr) state_.arc_absolute = w.code(arc_distance) == 901;
    if (w.g(motion) != nullptr) state_.motion = w.code(motion);

    if (const Word* first = w.first_of(axis_words)) {
        const int column = w.g(motion) != nullptr ? w.g(motion)->column : first->column;
        if (state_.motion < 0)
            at.fail(first->column, cat(first->letter, " word with no motion in effect: program G0 or G1 first"));
        const AxisVector target = target_of(w);
        for (std::size_t a = 0; a < axis_words.size(); ++a)
            if (const Word* word = w.get(axis_words[a]); word != nullptr && !(std::abs(target[static_cast<Eigen::Index>(a)]) <= max_coordinate))
                at.fail(word->column, cat(word->letter, " word '", word->text, "': the end point is beyond +-1e6 machine units"));
        if (is_arc(state_.motion)) arc(w, target, column, at);
        else line(target, column, at);
    }
    return w.get('M') != nullptr;
}

// P belongs to G64 or to an arc (turns), Q to G64, I J K R to an arc.
void Interpreter::check_word_use(const LineWords& w, const Where& at) const {
    const int motion_after = w.g(motion) != nullptr ? w.code(motion) : state_.motion;
    const bool has_axes = w.first_of(axis_words) != nullptr;
    const bool arc_move = is_arc(motion_after) && has_axes;
    const bool g64 = w.g(control) != nullptr && w.code(control) == 640;
    if (const Word* p = w.get('P')) {
        if (g64 && arc_move)
            at.fail(p->column, cat("word 'P' is used by both G64 and ", g_name(motion_after),
                                   ": put them on separate lines"));
        if (!g64 && !arc_move) at.fail(p->column, "word 'P' with no G64, G2 or G3 to use it");
    }
    if (const Word* q = w.get('Q'); q != nullptr && !g64) at.fail(q->column, "word 'Q' with no G64 to use it");
    if (const Word* c = w.first_of("IJKR"); c != nullptr && !arc_move) {
        if (is_arc(motion_after))
            at.fail(c->column, cat("word '", c->letter, "' with no axis word: an arc needs its end point"));
        at.fail(c->column, cat("word '", c->letter, "' with no G2 or G3 to use it"));
    }
}

// G61 / G61.1 stop exactly; G64 [P tolerance] [Q naive-CAM tolerance, accepted and ignored].
void Interpreter::set_control_mode(const LineWords& w, const Where& at) {
    if (w.g(control) == nullptr) return;
    const bool g64 = w.code(control) == 640;
    const Word* p = g64 ? w.get('P') : nullptr;
    if (p != nullptr && p->value < 0.0) at.fail(p->column, "G64 P must not be negative");
    if (const Word* q = w.get('Q'); q != nullptr && q->value < 0.0) at.fail(q->column, "G64 Q must not be negative");
    state_.termination = g64 ? Termination::blend : Termination::exact_stop;
    state_.tolerance = !g64 ? 0.0
                       : p == nullptr ? machine_.default_tolerance
                       : p->value == 0.0 ? infinity : p->value * state_.scale;
}

// End point of the line's move: linear axes in program units, A B C in degrees.
AxisVector Interpreter::target_of(const LineWords& w) const {
    AxisVector target = position_;
    for (Eigen::Index a = 0; a < max_axes; ++a) {
        const Word* word = w.get(axis_letters[static_cast<std::size_t>(a)]);
        if (word == nullptr) continue;
        const double value = word->value * (is_rotary(a) ? 1.0 : state_.scale);
        target[a] = (state_.incremental ? position_[a] : 0.0) + value;
    }
    return target;
}

// G0 / G1: F along the X Y Z length, else U V W, else A B C (deg/min); G0 as fast as the limits allow.
void Interpreter::line(const AxisVector& target, int column, const Where& at) {
    const bool rapid = state_.motion == 0;
    if (!rapid && state_.feed <= 0.0) at.fail(column, "cannot do G1 with zero feed rate: program an F word first");
    const AxisVector delta = target - position_;
    const MoveLengths lengths = move_lengths(delta);
    if (!lengths.moves()) return;
    const double path = lengths.feed_length();
    const double programmed = (lengths.linear() ? state_.feed : state_.angular_feed) / 60.0;
    const double cap = speed_cap(delta, path, lengths.linear(), machine_.limits);
    const double speed = rapid ? cap : std::min(programmed, cap);
    if (!std::isfinite(speed)) at.fail(column, "G0 needs the axes' MAX_VELOCITY: this machine has no rapid speed");
    push(target, speed * (lengths.all / path), state_.termination, state_.tolerance,
         rapid ? MotionType::traverse : MotionType::feed, column, at);
}

// G2 / G3 as equal-angle chords, all at one speed along the X Y Z helix.
void Interpreter::arc(const LineWords& w, const AxisVector& target, int column, const Where& at) {
    const ArcPlane plane = arc_plane(state_.plane);
    const Eigen::Vector2d centre = arc_centre(w, target, column, at);
    const int turns = arc_turns(w, at);
    Arc geometry;
    int chords = 0;
    try {
        geometry = make_arc(plane, position_, target, centre, state_.motion == 20, turns, arc_tolerances(state_.scale));
        chords = chord_count(geometry, machine_.arc_chord_tolerance);
    } catch (const ArcError& e) {
        at.fail(column, e.what());
    }
    if (const std::size_t made = blocks_.size(); static_cast<std::size_t>(chords) > machine_.max_program_blocks - made)
        at.fail(column, cat(too_many_blocks(), ": this arc's ", std::to_string(chords), " chords come after ",
                            std::to_string(made), made == 1 ? " block" : " blocks",
                            " (a coarser [FIRTP]ARC_CHORD_TOLERANCE needs fewer)"));

    // Inside the arc the chords blend; in G61 / G61.1 with the machine's tolerance.
    const bool blend = state_.termination == Termination::blend;
    const double inner_tolerance = blend ? state_.tolerance : machine_.default_tolerance;
    const double length = geometry.helix_length();
    const double chord_path = length / chords;  // each chord's share of the arc
    const double radius = std::min(geometry.start_radius, geometry.end_radius);
    double speed = state_.feed / 60.0;
    if (filters_) speed = std::min(speed, arc_speed_limit(*filters_, radius, inner_tolerance));
    AxisVector from = position_;
    for (int k = 1; k <= chords; ++k) {
        const AxisVector to = geometry.point(static_cast<double>(k) / chords);
        if (move_lengths(to - from).all <= zero_length)
            at.fail(column, "the arc's chords would be shorter than 1e-9 mm: raise [FIRTP]ARC_CHORD_TOLERANCE");
        speed = std::min(speed, speed_cap(to - from, chord_path, true, machine_.limits));
        from = to;
    }

    from = position_;
    for (int k = 1; k <= chords; ++k) {
        const AxisVector to = geometry.point(static_cast<double>(k) / chords);
        const double feed = move_lengths(to - from).all * speed / chord_path;  // duration = chord_path / speed
        const bool last = k == chords;
        push(to, feed, last ? state_.termination : Termination::blend, last ? state_.tolerance : inner_tolerance,
             MotionType::feed, column, at);
        from = to;
    }
}

// Centre in the plane's (first, second) coordinates, from I J K (offsets, or absolute in G90.1) or R.
Eigen::Vector2d Interpreter::arc_centre(const LineWords& w, const AxisVector& target, int column,
                                        const Where& at) const {
    const ArcPlane plane = arc_plane(state_.plane);
    const std::string name = g_name(state_.motion);
    const Word* r = w.get('R');
    const Word* ijk = w.first_of(centre_letters);
    const char first = centre_letters[static_cast<std::size_t>(plane.first)];
    const char second = centre_letters[static_cast<std::size_t>(plane.second)];
    if (r == nullptr && ijk == nullptr)
        at.fail(column, cat(name, " in the ", plane_name(plane), " needs its centre: ", first, " and ", second,
                            " words, or R"));
    if (r != nullptr && ijk != nullptr)
        at.fail(std::max(r->column, ijk->column), "an arc takes either R or I J K words, not both");
    if (state_.feed <= 0.0) at.fail(column, cat("cannot do ", name, " with zero feed rate: program an F word first"));

    const Eigen::Vector2d start(position_[plane.first], position_[plane.second]);
    if (r != nullptr) {
        const Eigen::Vector2d end(target[plane.first], target[plane.second]);
        try {
            return centre_from_radius(start, end, r->value * state_.scale, state_.motion == 20,
                                      arc_tolerances(state_.scale).min_radius);
        } catch (const ArcError& e) {
            at.fail(r->column, e.what());
        }
    }
    const char off_plane = centre_letters[static_cast<std::size_t>(plane.normal)];
    if (const Word* off = w.get(off_plane))
        at.fail(off->column, cat(off_plane, " word given for an arc in the ", plane_name(plane), ": use ", first,
                                 " and ", second));
    Eigen::Vector2d centre = state_.arc_absolute ? Eigen::Vector2d::Zero() : start;
    for (const auto& [letter, index] : {std::pair{first, 0}, std::pair{second, 1}}) {
        const Word* word = w.get(letter);
        if (word == nullptr && state_.arc_absolute)
            at.fail(column, cat(letter, " word missing for an arc with an absolute centre (G90.1)"));
        if (word != nullptr) centre[index] += word->value * state_.scale;
    }
    return centre;
}

// P n: n turns, the last one ending at the end point (P1 is a plain arc).
int Interpreter::arc_turns(const LineWords& w, const Where& at) const {
    const Word* p = w.get('P');
    if (p == nullptr) return 1;
    if (p->value < 1.0 || p->value > max_turns || p->value != std::floor(p->value))
        at.fail(p->column, cat(g_name(state_.motion), " P is the number of turns: a whole number from 1 to ",
                               std::to_string(max_turns)));
    return static_cast<int>(p->value);
}

// The program is kept whole in memory, 112 bytes a block: a few short lines of many-chord arcs
// would otherwise fill it.
std::string Interpreter::too_many_blocks() const {
    const std::string most = std::to_string(machine_.max_program_blocks);
    return cat("the program needs more than ", most, " blocks ([FIRTP]MAX_PROGRAM_BLOCKS = ", most, ")");
}

void Interpreter::push(const AxisVector& target, double feed, Termination termination, double tolerance,
                       MotionType type, int column, const Where& at) {
    // An arc of a huge radius can pass far beyond its end points.
    if (!(target.cwiseAbs().maxCoeff() <= max_coordinate))
        at.fail(column, "the move passes beyond +-1e6 machine units");
    if (!(std::isfinite(feed) && feed > 0.0)) at.fail(column, "the move's speed is not a positive finite number");
    if (blocks_.size() >= machine_.max_program_blocks) at.fail(column, too_many_blocks());
    Block block;
    block.target = target;
    block.feed = feed;
    block.termination = termination;
    block.tolerance = tolerance;
    block.type = type;
    block.line = at.line;
    blocks_.push_back(block);
    position_ = target;
}

}  // namespace firtp::gcode
