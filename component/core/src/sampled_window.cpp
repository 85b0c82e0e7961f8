#include <firtp/sampled_window.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::int64_t never = std::numeric_limits<std::int64_t>::max();

// Distance from a point to the segment a-b over the first n axes (the machine's).
double chord_distance(const AxisVector& point, const AxisVector& a, const AxisVector& b, int n) {
    double len2 = 0.0, along = 0.0;
    for (int i = 0; i < n; ++i) {
        const double ab = b[i] - a[i];
        len2 += ab * ab;
        along += (point[i] - a[i]) * ab;
    }
    const double u = len2 > 0.0 ? std::clamp(along / len2, 0.0, 1.0) : 0.0;
    double d2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double d = point[i] - a[i] - u * (b[i] - a[i]);
        d2 += d * d;
    }
    return std::sqrt(d2);
}

std::int64_t ceil_tick(std::int64_t tick, double offset) { return tick + (offset > 0.0 ? 1 : 0); }

// |v|, |a|, |j| of one axis against its limits (0 = none); only the first `known` are checked.
bool axis_within(const AxisLimits& l, double v, double a, double j, int known = 3) {
    constexpr double slack = 1.0 + 1e-9;
    if (known >= 1 && l.max_velocity > 0.0 && std::abs(v) > l.max_velocity * slack) return false;
    if (known >= 2 && l.max_acceleration > 0.0 && std::abs(a) > l.max_acceleration * slack) return false;
    if (known >= 3 && l.max_jerk > 0.0 && std::abs(j) > l.max_jerk * slack) return false;
    return true;
}

// Ticks a candidate must be checked at: its start to one window after its end, without the
// middle of a long pulse where it moves alone along its own line.
struct Ranges {
    std::int64_t a0, a1, b0, b1;  // [a0, a1] and [b0, b1], b empty when b0 > b1
};

}  // namespace

SampledWindow::SampledWindow(const FirChain& chain, const PlannerParameters& parameters, std::size_t max_corners)
    : chain_(&chain), period_(parameters.period), meaning_(parameters.tolerance_meaning), limits_(planned_limits(parameters)),
      axes_(std::clamp(parameters.limits.axes, 1, max_axes)),
      window_ticks_(static_cast<std::int64_t>(std::ceil(chain.delay() / parameters.period)) + 2),
      tail_(static_cast<std::size_t>(window_ticks_) + 1), prefix_(tail_.size() + 1),
      corners_(std::max<std::size_t>(max_corners, 4)) {
    for (int a = 0; a < limits_.axes; ++a) {
        const AxisLimits& l = limits_.axis[a];
        check_limits_ = check_limits_ || l.max_velocity > 0.0 || l.max_acceleration > 0.0 || l.max_jerk > 0.0;
    }
    reset(AxisVector::Zero(), 0);
}

void SampledWindow::reset(const AxisVector& position, std::int64_t tick) {
    rest_ = position;
    at_rest_ = {position, AxisVector::Zero(), AxisVector::Zero(), AxisVector::Zero()};
    tail_tick_ = tick;
    for (Sample& s : tail_) s = {position, AxisVector::Zero(), AxisVector::Zero(), AxisVector::Zero()};
    for (AxisVector& h : finalized_history_) h = position;  // it has been resting there
    finalized_known_ = 3;
    corner_head_ = 0;
    corner_count_ = 1;
    cursor_ = 0;
    corner(0) = {position, infinity, infinity, false, never, position, never, never};
    sweep_tail();
}

void SampledWindow::sweep_tail() {
    prefix_[0] = start_sweep();
    prefix_valid_ = 1;
}

const SampledWindow::Sweep& SampledWindow::prefix(std::size_t i) const {
    for (; prefix_valid_ <= i; ++prefix_valid_) {
        prefix_[prefix_valid_] = prefix_[prefix_valid_ - 1];
        const_cast<SampledWindow*>(this)->visit(prefix_[prefix_valid_], tail_[prefix_valid_ - 1].position,
                                                tail_tick_ + static_cast<std::int64_t>(prefix_valid_) - 1, false,
                                                AxisVector::Zero(), never);
    }
    return prefix_[i];
}

void SampledWindow::set_corner_tolerance(double epsilon, bool bound) {
    Corner& c = corner(corner_count_ - 1);
    c.epsilon = epsilon;
    c.bound = bound && std::isfinite(epsilon);
}

const SampledWindow::Sample& SampledWindow::committed(std::int64_t tick) const {
    const std::int64_t i = tick - tail_tick_;
    if (i >= 0 && i < static_cast<std::int64_t>(tail_.size())) return tail_[static_cast<std::size_t>(i)];
    return at_rest_;
}

SampledWindow::Sample SampledWindow::with(const Candidate& c, std::int64_t tick, const Sample& base) const {
    const double t = static_cast<double>(tick - c.start_tick) * period_ - c.start_offset;
    if (t <= 0.0) return base;
    const StepSample s = chain_->pulse(t, c.tv);
    return {base.position + c.delta * s.position, base.velocity + c.delta * s.velocity,
            base.acceleration + c.delta * s.acceleration, base.jerk + c.delta * s.jerk};
}

bool SampledWindow::within_limits(const Sample& s) const {
    for (int a = 0; a < limits_.axes; ++a)
        if (!axis_within(limits_.axis[a], s.velocity[a], s.acceleration[a], s.jerk[a])) return false;
    return true;
}

double SampledWindow::segment_distance(const AxisVector& p, std::size_t i, const AxisVector& candidate_delta) const {
    const Corner& c = corner(i);
    // The last junction's segment is the candidate's, not yet committed.
    const AxisVector end = i + 1 == corner_count_ ? AxisVector(c.point + candidate_delta) : c.segment_end;
    return chord_distance(p, c.point, end, axes_);
}

double SampledWindow::path_distance(const AxisVector& p, std::size_t cursor, const AxisVector& candidate_delta) const {
    double best = infinity;
    const std::size_t from = cursor > 0 ? cursor - 1 : 0, to = std::min(corner_count_, cursor + 3);
    for (std::size_t i = from; i < to; ++i) best = std::min(best, segment_distance(p, i, candidate_delta));
    return best;
}

bool SampledWindow::differences_within_limits(const Sweep& w, const AxisVector& p) const {
    const double T = period_;
    for (int a = 0; a < limits_.axes; ++a) {
        const double p0 = p[a], p1 = w.history[0][a], p2 = w.history[1][a], p3 = w.history[2][a];
        if (!axis_within(limits_.axis[a], (p0 - p1) / T, (p0 - 2 * p1 + p2) / (T * T),
                         (p0 - 3 * p1 + 3 * p2 - p3) / (T * T * T), w.known))
            return false;
    }
    return true;
}

SampledWindow::Sweep SampledWindow::start_sweep() const {
    Sweep w{cursor_, {infinity, infinity, infinity},
            {finalized_history_[0], finalized_history_[1], finalized_history_[2]}, finalized_known_};
    for (std::size_t j = 0; j < 3; ++j)
        if (cursor_ + j < corner_count_) w.closest[j] = corner(cursor_ + j).best;
    return w;
}

bool SampledWindow::visit(Sweep& w, const AxisVector& p, std::int64_t tick, bool keep,
                          const AxisVector& candidate_delta, std::int64_t candidate_start) {
    // Closest approach of the chord from the previous sample to junction i. At speed the tool may
    // pass several short segments between two samples: each junction it passes meets the chord.
    auto approach = [&](std::size_t i, double best) {
        return w.known > 0 ? std::min(best, chord_distance(corner(i).point, w.history[0], p, axes_)) : best;
    };
    for (std::size_t j = 0; j < 3 && w.cursor + j < corner_count_; ++j) w.closest[j] = approach(w.cursor + j, w.closest[j]);
    bool ok = true;
    // The tool has passed a junction once the segment after it is as near as the one before. Ties
    // advance: a retract and its plunge lie on one line, and the cursor must not stay behind. Time
    // bounds it both ways: not before the pulse leaving the junction has begun, and for certain once
    // the pulse arriving there has filtered out, wherever a path passing back near itself seems to be.
    auto started = [&](std::size_t i) {
        return (i + 1 == corner_count_ ? candidate_start : corner(i).start_tick) <= tick;
    };
    while (w.cursor + 1 < corner_count_ && started(w.cursor + 1) &&
           (corner(w.cursor + 1).passed_tick <= tick ||
            segment_distance(p, w.cursor + 1, candidate_delta) <= segment_distance(p, w.cursor, candidate_delta))) {
        const Corner& passed = corner(w.cursor);
        if (meaning_ == ToleranceMeaning::corner_point && passed.bound && w.closest[0] > passed.epsilon) ok = false;
        w.closest[0] = w.closest[1];
        w.closest[1] = w.closest[2];
        w.closest[2] = w.cursor + 3 < corner_count_ ? approach(w.cursor + 3, corner(w.cursor + 3).best) : infinity;
        ++w.cursor;
    }
    if (keep)
        for (std::size_t j = 0; j < 3 && w.cursor + j < corner_count_; ++j) corner(w.cursor + j).best = w.closest[j];
    w.history[2] = w.history[1];
    w.history[1] = w.history[0];
    w.history[0] = p;
    w.known = std::min(w.known + 1, 3);
    return ok;
}

bool SampledWindow::check_sample(Sweep& w, const Sample& s, std::int64_t tick, double contour_epsilon,
                                 const Candidate& c, std::int64_t candidate_start, bool consecutive) const {
    if (check_limits_ && !within_limits(s)) return false;
    if (check_limits_ && consecutive && !differences_within_limits(w, s.position)) return false;
    // Find the junction the tool is at first: between samples it may pass several short segments.
    if (!const_cast<SampledWindow*>(this)->visit(w, s.position, tick, false, c.delta, candidate_start))  // no writes
        return false;
    return meaning_ != ToleranceMeaning::contour || !std::isfinite(contour_epsilon) ||
           path_distance(s.position, w.cursor, c.delta) <= contour_epsilon;
}

bool SampledWindow::feasible(const Candidate& c, int stride) const {
    const std::int64_t start = ceil_tick(c.start_tick, c.start_offset);
    const double end_time = static_cast<double>(c.start_tick) * period_ + c.start_offset + c.tv;
    const auto end = static_cast<std::int64_t>(std::floor(end_time / period_));
    Ranges r{tail_tick_, end + window_ticks_, 1, 0};
    if (end - start > 2 * window_ticks_) r = {tail_tick_, start + window_ticks_, end - 1, end + window_ticks_};

    // Tightest tolerance among the junctions the samples can still approach.
    double contour_epsilon = infinity;
    for (std::size_t i = cursor_ > 0 ? cursor_ - 1 : 0; i < corner_count_; ++i)
        if (corner(i).bound) contour_epsilon = std::min(contour_epsilon, corner(i).epsilon);

    // Committed samples before the candidate starts were checked when they were committed: start
    // from the sweep state there.
    const std::int64_t skip = std::clamp<std::int64_t>(start - 1 - tail_tick_, 0, static_cast<std::int64_t>(tail_.size()));
    Sweep w = prefix(static_cast<std::size_t>(skip));
    // After a stop (Tk = 0) the candidate's first sample rests on the junction: a stride takes it
    // too, else the chord past it cuts the corner, by more than a tight epsilon at any feed.
    bool first_taken = stride == 1 || start <= r.a0 + skip || c.start_offset != 0.0 ||
                       committed(start).velocity != AxisVector::Zero();
    for (std::int64_t k = r.a0 + skip; k <= r.a1; k = k + stride <= r.a1 || k == r.a1 ? k + stride : r.a1) {
        if (k > tail_tick_ + window_ticks_ && k < start - 1) k = start - 1;  // at rest until the start
        if (!first_taken && k > start) {
            first_taken = true;
            if (!check_sample(w, with(c, start, committed(start)), start, contour_epsilon, c, start, false))
                return false;
        }
        if (!check_sample(w, with(c, k, committed(k)), k, contour_epsilon, c, start, stride == 1)) return false;
    }
    w.known = 0;  // the middle of a long pulse is skipped
    for (std::int64_t k = r.b0; k <= r.b1; k = k + stride <= r.b1 || k == r.b1 ? k + stride : r.b1)
        if (!check_sample(w, with(c, k, committed(k)), k, contour_epsilon, c, start, stride == 1)) return false;
    // At rest on the last point: what is left must be within tolerance too.
    if (meaning_ == ToleranceMeaning::corner_point)
        for (std::size_t j = 0; j < 3 && w.cursor + j < corner_count_; ++j)
            if (corner(w.cursor + j).bound && w.closest[j] > corner(w.cursor + j).epsilon) return false;
    return true;
}

void SampledWindow::release_passed_corners(std::int64_t tick) {
    // Release junctions the tool has passed and no later sample can approach.
    while (corner_count_ > 1 && cursor_ > 0 && corner(0).release_tick < tick) {
        corner_head_ = (corner_head_ + 1) % corners_.size();
        --corner_count_;
        --cursor_;
    }
}

void SampledWindow::commit(const Candidate& c) {
    const std::int64_t start = ceil_tick(c.start_tick, c.start_offset);
    const double end_time = static_cast<double>(c.start_tick) * period_ + c.start_offset + c.tv;
    const auto end = static_cast<std::int64_t>(std::ceil(end_time / period_));

    // Samples before the candidate's end can no longer change: fold them into the junctions.
    Sweep w = start_sweep();
    auto fold = [&](std::int64_t from, std::int64_t to) {
        for (std::int64_t k = from; k < to; ++k) {
            if (k > tail_tick_ + window_ticks_ && k < start - 1) k = start - 1;  // at rest until the start
            visit(w, with(c, k, committed(k)).position, k, true, c.delta, start);
        }
    };
    if (end - start > 2 * window_ticks_) {
        fold(tail_tick_, start + window_ticks_);
        w.known = 0;
        fold(end - 1, end);
    } else {
        fold(tail_tick_, end);
    }
    cursor_ = w.cursor;
    for (int i = 0; i < 3; ++i) finalized_history_[i] = w.history[i];
    finalized_known_ = w.known;

    // The new tail, rewritten in place: entry i reads the old entry (end - tail_tick_) + i >= i.
    for (std::size_t i = 0; i < tail_.size(); ++i) {
        const std::int64_t k = end + static_cast<std::int64_t>(i);
        tail_[i] = with(c, k, committed(k));
    }
    tail_tick_ = end;
    rest_ += c.delta;
    at_rest_.position = rest_;

    // The junction where this pulse started stays reachable until its window ends; the one at its
    // end starts the next segment.
    Corner& from = corner(corner_count_ - 1);
    from.release_tick = end + window_ticks_;
    from.segment_end = from.point + c.delta;
    from.start_tick = start;
    if (corner_count_ == corners_.size()) {  // full: forget the oldest
        corner_head_ = (corner_head_ + 1) % corners_.size();
        --corner_count_;
        if (cursor_ > 0) --cursor_;
    }
    ++corner_count_;
    corner(corner_count_ - 1) = {rest_, infinity, infinity, false, never, rest_, never, end + window_ticks_};
    release_passed_corners(end);
    sweep_tail();
}

}  // namespace firtp
