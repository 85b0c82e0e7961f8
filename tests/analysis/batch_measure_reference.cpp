// The batch measurement as it was before it was streamed (commit ae6ec3c), kept only as the oracle
// of tests/analysis/measure_stream_test.cpp: the streamed measure() must equal it bit for bit.
#include "batch_measure_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace firtp::reference {
namespace {

struct Segment {
    AxisVector start;
    AxisVector delta;  // end - start
    AxisVector unit;   // delta / |delta|
    double length2 = 0.0;
};

// Sums in axis order, as the stream does (the same roundings, so the two compare exactly).
double dot(const AxisVector& x, const AxisVector& y) {
    double sum = 0.0;
    for (int a = 0; a < max_axes; ++a) sum += x[a] * y[a];
    return sum;
}

double distance(const AxisVector& p, const Segment& s) {
    const AxisVector from_start = p - s.start;
    const double t = s.length2 > 0.0 ? std::clamp(dot(from_start, s.delta) / s.length2, 0.0, 1.0) : 0.0;
    const AxisVector r = from_start - t * s.delta;
    return std::sqrt(dot(r, r));
}

Segment chord(const AxisVector& a, const AxisVector& b) {
    Segment s;
    s.start = a;
    s.delta = b - a;
    s.length2 = dot(s.delta, s.delta);
    return s;
}

// Zero-length blocks (as the planner skips them) repeat a point; drop the repeats.
std::vector<AxisVector> distinct_points(std::span<const AxisVector> points) {
    std::vector<AxisVector> out;
    for (const AxisVector& p : points)
        if (out.empty() || (p - out.back()).norm() >= min_block_length) out.push_back(p);
    return out;
}

std::vector<Segment> segments_of(const std::vector<AxisVector>& points) {
    std::vector<Segment> out;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        Segment s;
        s.start = points[k];
        s.delta = points[k + 1] - points[k];
        s.length2 = s.delta.squaredNorm();
        s.unit = s.length2 > 0.0 ? AxisVector(s.delta / std::sqrt(s.length2)) : AxisVector::Zero();
        out.push_back(s);
    }
    return out;
}

// Distances closer than this count as equal (rounding on overlapping segments).
double tie_tolerance(const std::vector<AxisVector>& points) {
    double scale = 1.0;
    for (const AxisVector& p : points) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    return 1e-10 * scale;
}

struct Tracking {
    std::vector<std::size_t> segment;  // per sample, never decreasing
    double max_distance = 0.0;         // largest distance of a sample from the polyline
};

// Forward tracking step for sample p moving along `motion`, last tracked to segment k:
// moves on when one of the next two segments is closer (two, so that cutting across a short
// detour cannot stall the tracking), or when the next one is as close (a corner point, or the
// overlapping segments of a reversal) and fits the direction of motion better.
// `stray`: how far samples have strayed from the path so far; the tool may cut across a detour
// of that order (a narrow U of micrometre blocks within its tolerance), so the search for a
// closer segment reaches over a few times that much path as well.
std::size_t advance(const std::vector<Segment>& segments, const AxisVector& p, const AxisVector& motion,
                    std::size_t k, double tie, double stray) {
    const std::size_t last = segments.size() - 1;
    double d = distance(p, segments[k]);
    const double step = motion.norm() + tie;  // how far the tool can have gone since the last sample
    const double reach = step + 4.0 * stray;
    while (k < last) {
        const double next = distance(p, segments[k + 1]);
        // Further segments, as long as the ones skipped are short enough to pass within a step.
        std::size_t jump = 0;
        double after = std::numeric_limits<double>::infinity(), skipped = 0.0;
        for (std::size_t j = k + 2; j <= last && skipped <= reach; ++j) {
            skipped += std::sqrt(segments[j - 1].length2);
            if (const double dj = distance(p, segments[j]); dj < after) after = dj, jump = j;
        }
        if (jump != 0 && after < std::min(d, next) - tie) {
            k = jump;
            d = after;
            continue;
        }
        const bool closer = next < d - tie;
        const bool tied = next <= d + tie && motion.dot(segments[k + 1].unit) > motion.dot(segments[k].unit);
        if (!closer && !tied) break;
        ++k;
        d = next;
    }
    return k;
}

// Assigns every sample a segment, never going back, so that a reversal or a revisited point is
// not mistaken for an earlier part of the path; distances are taken over segments k-1 .. k+2.
Tracking track(std::span<const AxisState> samples, const std::vector<Segment>& segments, double tie) {
    Tracking out;
    out.segment.reserve(samples.size());
    const std::size_t n = samples.size();
    const std::size_t last = segments.size() - 1;
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const AxisVector& p = samples[i].position;
        out.segment.push_back(k);
        if (!p.allFinite()) continue;  // reported by Measured::finite
        const AxisVector motion = samples[std::min(i + 1, n - 1)].position - samples[i > 0 ? i - 1 : 0].position;
        k = advance(segments, p, motion, k, tie, out.max_distance);
        out.segment.back() = k;
        double d = std::numeric_limits<double>::infinity();
        for (std::size_t s = k > 0 ? k - 1 : 0; s <= std::min(k + 2, last); ++s) d = std::min(d, distance(p, segments[s]));
        out.max_distance = std::max(out.max_distance, d);
    }
    return out;
}

// Closest approach to point j of the chords between samples tracked to segments first..last.
double closest_approach(std::span<const AxisState> samples, const AxisVector& point,
                        const std::vector<std::size_t>& segment, std::size_t first, std::size_t last) {
    auto lo = static_cast<std::size_t>(std::lower_bound(segment.begin(), segment.end(), first) - segment.begin());
    auto hi = static_cast<std::size_t>(std::upper_bound(segment.begin(), segment.end(), last) - segment.begin());
    if (lo == hi) {  // the tracking jumped past: use the samples either side of the jump
        lo = lo > 0 ? lo - 1 : 0;
        hi = std::min(hi + 1, samples.size());
    }
    // The drives go straight from sample to sample: measure the chords, including the ones
    // entering and leaving the tracked range.
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = lo > 0 ? lo - 1 : 0; i < hi && i + 1 < samples.size(); ++i)
        best = std::min(best, distance(point, chord(samples[i].position, samples[i + 1].position)));
    if (samples.size() == 1 || hi == samples.size()) best = std::min(best, (samples.back().position - point).norm());
    return best;
}

// Closest approach to each interior point j over the samples tracked to segment j-1 or j.
std::vector<double> corner_errors(std::span<const AxisState> samples, const std::vector<AxisVector>& points,
                                  const std::vector<std::size_t>& segment) {
    std::vector<double> out;
    for (std::size_t j = 1; j + 1 < points.size(); ++j) out.push_back(closest_approach(samples, points[j], segment, j - 1, j));
    return out;
}

void measure_derivatives(std::span<const AxisState> samples, double period, Measured& m) {
    const std::size_t n = samples.size();
    auto p = [&](std::size_t i) -> const AxisVector& { return samples[i].position; };
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const AxisVector step = p(i + 1) - p(i);
        m.max_velocity = m.max_velocity.cwiseMax(step.cwiseAbs());
        m.max_path_speed = std::max(m.max_path_speed, step.norm());
    }
    for (std::size_t i = 1; i + 1 < n; ++i)
        m.max_acceleration = m.max_acceleration.cwiseMax((p(i + 1) - 2.0 * p(i) + p(i - 1)).cwiseAbs());
    for (std::size_t i = 1; i + 2 < n; ++i)
        m.max_jerk = m.max_jerk.cwiseMax((p(i + 2) - 3.0 * p(i + 1) + 3.0 * p(i) - p(i - 1)).cwiseAbs());
    m.max_velocity /= period;
    m.max_path_speed /= period;
    m.max_acceleration /= period * period;
    m.max_jerk /= period * period * period;
}

}  // namespace

Measured measure_batch(std::span<const AxisState> samples, std::span<const AxisVector> points, double period) {
    Measured m;
    for (const AxisState& s : samples) m.finite = m.finite && s.position.allFinite();
    if (samples.empty()) return m;
    m.cycle_time = samples.back().time;
    m.end_position = samples.back().position;
    if (samples.size() < 2) return m;

    if (period > 0.0) measure_derivatives(samples, period, m);

    const std::vector<AxisVector> distinct = distinct_points(points);
    if (distinct.size() == 1)  // a program that never moves: the polyline is one point
        for (const AxisState& s : samples) m.max_contour_error = std::max(m.max_contour_error, (s.position - distinct[0]).norm());
    if (distinct.size() < 2) return m;

    const Tracking tracking = track(samples, segments_of(distinct), tie_tolerance(distinct));
    m.max_contour_error = tracking.max_distance;
    m.corner_errors = corner_errors(samples, distinct, tracking.segment);
    for (double e : m.corner_errors) m.max_corner_error = std::max(m.max_corner_error, e);
    return m;
}

}  // namespace firtp::reference
