// Measures a sampled trajectory against the programmed polyline (see measure.hpp), one sample at a
// time: a sample is tracked to a segment once the next one shows its direction of motion, and the
// chord between two tracked samples goes to the corners it can be nearest to.
#include <firtp/measure.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace firtp {
namespace {

using Segment = MeasureStream::Segment;
constexpr double inf = std::numeric_limits<double>::infinity();

// Distances are taken over at least this many axes (a fixed count the compiler unrolls: X Y Z).
constexpr int least_dims = 3;

// Over the first `dims` axes only (the others are zero in every point and sample so far: see
// MeasureStream::widen), summed in axis order.
template <int Dims>
double distance_over(const AxisVector& p, const Segment& s, int dims) {
    const int n = Dims > 0 ? Dims : dims;
    std::array<double, max_axes> from_start;
    double along = 0.0;
    for (int a = 0; a < n; ++a) {
        from_start[a] = p[a] - s.start[a];
        along += from_start[a] * s.delta[a];
    }
    const double t = s.length2 > 0.0 ? std::clamp(along / s.length2, 0.0, 1.0) : 0.0;
    double sum = 0.0;
    for (int a = 0; a < n; ++a) {
        const double r = from_start[a] - t * s.delta[a];
        sum += r * r;
    }
    return std::sqrt(sum);
}

double distance(const AxisVector& p, const Segment& s, int dims) {
    return dims <= least_dims ? distance_over<least_dims>(p, s, dims) : distance_over<0>(p, s, dims);  // (zeros beyond dims add nothing)
}

void make_chord(Segment& s, const AxisVector& a, const AxisVector& b, int dims) {
    s.start = a;
    s.length2 = 0.0;
    for (int k = 0; k < std::max(dims, least_dims); ++k) {  // as far as distance() reads
        s.delta[k] = b[k] - a[k];
        s.length2 += s.delta[k] * s.delta[k];
    }
}

// The caller's points without repeats (zero-length blocks, as the planner skips them, repeat a
// point; a copy only where there are any: a long program's points are not held twice).
class SpanPoints : public PointSource {
public:
    explicit SpanPoints(std::span<const AxisVector> points) {
        const auto distinct = [](const AxisVector& a, const AxisVector& b) { return (b - a).norm() >= min_block_length; };
        bool repeats = false;
        for (std::size_t i = 1; i < points.size() && !repeats; ++i) repeats = !distinct(points[i - 1], points[i]);
        if (repeats) {
            for (const AxisVector& p : points)
                if (own_.empty() || distinct(own_.back(), p)) own_.push_back(p);
            points_ = own_;
        } else {
            points_ = points;
        }
        for (const AxisVector& p : points_) scale_ = std::max(scale_, p.cwiseAbs().maxCoeff());
    }
    std::size_t size() const override { return points_.size(); }
    double scale() const override { return scale_; }
    AxisVector next() override { return points_[next_++]; }

private:
    std::vector<AxisVector> own_;
    std::span<const AxisVector> points_;
    double scale_ = 1.0;
    std::size_t next_ = 0;
};

}  // namespace

MeasureStream::MeasureStream(std::span<const AxisVector> points, double period, CornerCallback on_corner)
    : own_(std::make_unique<SpanPoints>(points)), period_(period), on_corner_(std::move(on_corner)) {
    start(*own_);
}

MeasureStream::MeasureStream(PointSource& points, double period, CornerCallback on_corner)
    : period_(period), on_corner_(std::move(on_corner)) {
    start(points);
}

void MeasureStream::start(PointSource& points) {
    source_ = &points;
    size_ = points.size();
    if (size_ >= 2) last_ = size_ - 2;
    tie_ = 1e-10 * points.scale();  // distances closer than this count as equal (rounding on overlaps)
}

MeasureStream::~MeasureStream() = default;

void MeasureStream::widen(const AxisVector& x) {
    for (int a = max_axes - 1; a >= dims_; --a)
        if (x[a] != 0.0) {
            dims_ = a + 1;
            for (Chord& c : chords_) c.index = Chord::none;  // made over fewer axes
            return;
        }
}

const AxisVector& MeasureStream::point(std::size_t j) {
    while (points_base_ + points_.size() <= j) {
        points_.push_back(source_->next());
        widen(points_.back());
    }
    return points_[j - points_base_];
}

// No later step looks below the older tracked sample's segment, the segments kept or an open corner.
void MeasureStream::release() {
    std::size_t low = std::min({tracked_[0], tracked_[1], window_base_});
    if (!open_.empty()) low = std::min(low, open_.front().first);
    for (; points_base_ < low && !points_.empty(); ++points_base_) points_.pop_front();
}

// Segments are made as the tracking reaches them and dropped behind it (it never goes back).
const Segment& MeasureStream::segment(std::size_t k) {
    while (window_base_ + window_.size() <= k) {
        const std::size_t j = window_base_ + window_.size();
        Segment s;
        s.start = point(j);
        s.delta = point(j + 1) - s.start;
        s.length2 = s.delta.squaredNorm();
        s.length = std::sqrt(s.length2);
        s.unit = s.length2 > 0.0 ? AxisVector(s.delta / s.length) : AxisVector::Zero();
        window_.push_back(s);
    }
    return window_[k - window_base_];
}

void MeasureStream::derivatives(std::size_t n) {
    const auto p = [&](std::size_t i) -> const AxisVector& { return recent(i); };
    if (n >= 1) {
        const AxisVector step = p(n) - p(n - 1);
        m_.max_velocity = m_.max_velocity.cwiseMax(step.cwiseAbs());
        m_.max_path_speed = std::max(m_.max_path_speed, step.norm());
    }
    if (n >= 2) {
        const std::size_t i = n - 1;
        m_.max_acceleration = m_.max_acceleration.cwiseMax((p(i + 1) - 2.0 * p(i) + p(i - 1)).cwiseAbs());
    }
    if (n >= 3) {
        const std::size_t i = n - 2;
        m_.max_jerk = m_.max_jerk.cwiseMax((p(i + 2) - 3.0 * p(i + 1) + 3.0 * p(i) - p(i - 1)).cwiseAbs());
    }
}

// Forward tracking step for sample i moving along `motion`, last tracked to segment k_:
// moves on when one of the next two segments is closer (two, so that cutting across a short
// detour cannot stall the tracking), or when the next one is as close (a corner point, or the
// overlapping segments of a reversal) and fits the direction of motion better.
// stray_: how far samples have strayed from the path so far; the tool may cut across a detour
// of that order (a narrow U of micrometre blocks within its tolerance), so the search for a
// closer segment reaches over a few times that much path as well. The segment is never earlier
// than the last one, so that a reversal or a revisited point is not mistaken for an earlier part
// of the path; distances are taken over segments k-1 .. k+2.
void MeasureStream::track(std::size_t i, const AxisVector& motion) {
    const AxisVector& p = recent(i);
    std::size_t& tracked = tracked_[i % 2];
    tracked = k_;
    if (!p.allFinite()) return;  // reported by Measured::finite
    std::size_t k = k_;
    // Each segment's distance from p found once for this sample (the scans below overlap), by its
    // index from k_ - 1 on (no scan looks below that); -1: not yet.
    std::array<double, 32> known;
    known.fill(-1.0);
    const std::size_t known_base = k > 0 ? k - 1 : 0;
    auto distance_to = [&](std::size_t j) {
        const std::size_t m = j - known_base;
        if (m < known.size() && known[m] >= 0.0) return known[m];
        const Segment& segment_j = segment(j);  // first: its points may widen dims_
        const double dj = distance(p, segment_j, dims_);
        if (m < known.size()) known[m] = dj;
        return dj;
    };
    double d = distance_to(k);
    const double step = motion.norm() + tie_;  // how far the tool can have gone since the last sample
    const double reach = step + 4.0 * stray_;
    while (k < last_) {
        const double next = distance_to(k + 1);
        // Further segments, as long as the ones skipped are short enough to pass within a step.
        std::size_t jump = 0;
        double after = inf, skipped = 0.0;
        for (std::size_t j = k + 2; j <= last_ && skipped <= reach; ++j) {
            skipped += segment(j - 1).length;
            if (const double dj = distance_to(j); dj < after) after = dj, jump = j;
        }
        if (jump != 0 && after < std::min(d, next) - tie_) {
            k = jump;
            d = after;
            continue;
        }
        const bool closer = next < d - tie_;
        const bool tied = next <= d + tie_ && motion.dot(segment(k + 1).unit) > motion.dot(segment(k).unit);
        if (!closer && !tied) break;
        ++k;
        d = next;
    }
    k_ = tracked = k;
    double nearest = inf;
    for (std::size_t s = k > 0 ? k - 1 : 0; s <= std::min(k + 2, last_); ++s) nearest = std::min(nearest, distance_to(s));
    stray_ = std::max(stray_, nearest);
    for (; window_base_ + 1 < k && !window_.empty(); ++window_base_) window_.pop_front();
}

// Distance of interior point j from the chord between samples c and c+1 (the drives go straight
// from sample to sample).
double MeasureStream::chord_distance(std::size_t c, std::size_t j) {
    const AxisVector& q = point(j);  // first: it may widen dims_
    Chord& chord = chords_[c % chords_.size()];  // a chord is asked for by several corners
    if (chord.index != c) {
        make_chord(chord.segment, recent(c), recent(c + 1), dims_);
        chord.index = c;
    }
    return distance(q, chord.segment, dims_);
}

void MeasureStream::close_corner(std::size_t j, double error) {
    if (keep_errors_) m_.corner_errors.push_back(error);  // corner j is entry j - 1: corners close in order
    m_.max_corner_error = std::max(m_.max_corner_error, error);
    if (on_corner_) on_corner_(j - 1, error);
}

void MeasureStream::close_open_below(std::size_t j) {
    for (; !open_.empty() && open_.front().first < j; open_.pop_front()) close_corner(open_.front().first, open_.front().second);
}

// Chord c between samples c and c+1, tracked to segments s0 <= s1. A corner j takes every chord
// touching a sample tracked to segment j-1 or j (s0 <= j <= s1 + 1), the ones entering and leaving
// included. A corner the tracking jumped past (s0 < j-1, j < s1) takes the chords either side of
// the jump; one before the first sample's segment, the first chord. has_next: chord c+1 exists.
void MeasureStream::chord(std::size_t c, bool has_next) {
    const std::size_t s0 = tracked_[c % 2], s1 = tracked_[(c + 1) % 2];
    if (c == 0)
        for (std::size_t j = 1; j < s0 && j <= last_; ++j) close_corner(j, std::min(inf, chord_distance(0, j)));
    for (std::size_t j = std::max<std::size_t>(s0, 1); j <= std::min(s1 + 1, last_); ++j) {
        if (j >= s0 + 2 && j < s1) continue;  // jumped past: below
        const double d = std::min(inf, chord_distance(c, j));  // NaN (a sample that is not finite) counts as none
        auto open = std::find_if(open_.begin(), open_.end(), [&](const auto& o) { return o.first == j; });
        if (open == open_.end()) open_.emplace_back(j, d);
        else open->second = std::min(open->second, d);
    }
    // Later chords start at s1: every corner below it is final.
    close_open_below(std::min(s0 + 2, s1));
    for (std::size_t j = s0 + 2; j < s1 && j <= last_; ++j) {
        double best = inf;
        if (c > 0) best = std::min(best, chord_distance(c - 1, j));
        best = std::min(best, chord_distance(c, j));
        if (has_next) best = std::min(best, chord_distance(c + 1, j));
        else best = std::min(best, (recent(c + 1) - point(j)).norm());
        close_corner(j, best);
    }
    close_open_below(s1);
}

void MeasureStream::add(const AxisState& sample) {
    const std::size_t n = n_++;
    recent_[n % recent_.size()] = sample.position;
    widen(sample.position);
    m_.finite = m_.finite && sample.position.allFinite();
    m_.cycle_time = sample.time;
    m_.end_position = sample.position;
    if (period_ > 0.0) derivatives(n);
    if (size_ == 1) lone_point_ = std::max(lone_point_, (sample.position - point(0)).norm());
    if (size_ < 2 || n == 0) return;
    const std::size_t i = n - 1;  // its direction of motion is known now
    track(i, recent(n) - recent(i > 0 ? i - 1 : 0));
    if (i >= 1) chord(i - 1, true);
    release();
}

Measured MeasureStream::finish() {
    const std::size_t n = n_;
    if (n < 2) {  // no differences, nothing to track
        m_.max_velocity.setZero();
        m_.max_path_speed = 0.0;
        return std::move(m_);
    }
    if (period_ > 0.0) {
        m_.max_velocity /= period_;
        m_.max_path_speed /= period_;
        m_.max_acceleration /= period_ * period_;
        m_.max_jerk /= period_ * period_ * period_;
    }
    if (size_ == 1) m_.max_contour_error = lone_point_;  // a program that never moves
    if (size_ < 2) return std::move(m_);

    track(n - 1, recent(n - 1) - recent(n - 2));
    chord(n - 2, false);
    const AxisVector& end = recent(n - 1);
    for (auto& [j, best] : open_) best = std::min(best, (end - point(j)).norm());
    close_open_below(last_ + 1);
    for (std::size_t j = tracked_[(n - 1) % 2] + 2; j <= last_; ++j)  // never reached: the last chord and the end
        close_corner(j, std::min(std::min(inf, chord_distance(n - 2, j)), (end - point(j)).norm()));
    m_.max_contour_error = stray_;
    return std::move(m_);
}

Measured measure(std::span<const AxisState> samples, std::span<const AxisVector> points, double period) {
    MeasureStream stream(points, period);
    for (const AxisState& s : samples) stream.add(s);
    return stream.finish();
}

}  // namespace firtp
