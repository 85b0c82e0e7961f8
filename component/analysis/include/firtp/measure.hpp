// Measures a sampled trajectory against the programmed path, independently of how it was planned:
// only the samples and the programmed points are used.
#pragma once

#include <firtp/types.hpp>

#include <array>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace firtp {

struct Measured {
    double cycle_time = 0.0;                  // time of the last sample
    std::vector<double> corner_errors;        // per interior programmed point: closest approach to it of the
                                              // path through the samples (straight from sample to sample)
    double max_corner_error = 0.0;
    double max_contour_error = 0.0;           // largest distance of a sample from the programmed polyline
    double max_path_speed = 0.0;              // |velocity| from first differences of positions
    AxisVector max_velocity = AxisVector::Zero();      // per axis, |first difference| / period
    AxisVector max_acceleration = AxisVector::Zero();  // per axis, |second difference| / period^2
    AxisVector max_jerk = AxisVector::Zero();          // per axis, |third difference| / period^3
    AxisVector end_position = AxisVector::Zero();
    bool finite = true;                       // no NaN or inf in any sample
};

// points: the start point followed by the end point of every block (zero-length blocks may repeat
// a point; they are ignored). Samples must be equally spaced by `period`.
Measured measure(std::span<const AxisState> samples, std::span<const AxisVector> points, double period);

// The programmed points in order, pulled as the measurement reaches them: the start point, then the
// end of every block that moves (consecutive points at least min_block_length apart).
class PointSource {
public:
    virtual ~PointSource() = default;
    virtual std::size_t size() const = 0;  // how many, known before the first is pulled
    virtual double scale() const = 0;      // max(1, largest |coordinate| of any point)
    virtual AxisVector next() = 0;         // the next point; called at most size() times
};

// A queue that is indexed from its front (cheaper than std::deque's blocks for measure's
// per-sample lookups); the front's slots are given back in batches.
template <class T>
class FrontQueue {
public:
    std::size_t size() const { return items_.size() - front_; }
    bool empty() const { return size() == 0; }
    T& operator[](std::size_t i) { return items_[front_ + i]; }
    const T& back() const { return items_.back(); }
    void push_back(const T& x) { items_.push_back(x); }
    void pop_front() {
        if (++front_ >= 256 && 2 * front_ >= items_.size()) {
            items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(front_));
            front_ = 0;
        }
    }

private:
    std::vector<T> items_;
    std::size_t front_ = 0;
};

// The same measurement, one sample at a time, with state bounded by the path the tool strays
// over (not by the number of samples): add() every sample in order, then finish(). The result is
// bit for bit measure()'s. `points` must outlive the stream; of a PointSource only the points
// near the tracking are held. `on_corner(index, error)` is told each corner error (index into
// Measured::corner_errors) as soon as no later sample can change it.
class MeasureStream {
public:
    using CornerCallback = std::function<void(std::size_t, double)>;

    MeasureStream(std::span<const AxisVector> points, double period, CornerCallback on_corner = {});
    MeasureStream(PointSource& points, double period, CornerCallback on_corner = {});
    ~MeasureStream();
    MeasureStream(const MeasureStream&) = delete;
    MeasureStream& operator=(const MeasureStream&) = delete;
    void add(const AxisState& sample);
    Measured finish();
    // Measured::corner_errors stays empty (the callback has them; max_corner_error is still found).
    void forget_corner_errors() { keep_errors_ = false; }

    // The segment of the program the newest tracked sample is on (blocks done, for progress).
    std::size_t segment() const { return k_; }

    struct Segment {
        AxisVector start = AxisVector::Zero();
        AxisVector delta = AxisVector::Zero();  // end - start
        AxisVector unit = AxisVector::Zero();   // delta / |delta|
        double length2 = 0.0;
        double length = 0.0;  // sqrt(length2)
    };

private:
    const AxisVector& recent(std::size_t i) const { return recent_[i % recent_.size()]; }
    const Segment& segment(std::size_t k);
    void derivatives(std::size_t n);
    void track(std::size_t i, const AxisVector& motion);
    double chord_distance(std::size_t c, std::size_t j);
    void start(PointSource& points);
    const AxisVector& point(std::size_t j);  // pulled from the source as needed
    void widen(const AxisVector& x);         // dims_ covers x's non-zero axes
    void release();                          // drops the points no later step looks at
    void chord(std::size_t c, bool has_next);
    void close_corner(std::size_t j, double error);
    void close_open_below(std::size_t j);

    std::unique_ptr<PointSource> own_;  // over the caller's span
    PointSource* source_ = nullptr;
    std::size_t size_ = 0;               // distinct programmed points
    FrontQueue<AxisVector> points_;      // from points_base_ on, as far as pulled
    std::size_t points_base_ = 0;
    std::size_t last_ = 0;            // index of the last segment
    double period_;
    double tie_ = 0.0;
    CornerCallback on_corner_;
    bool keep_errors_ = true;
    Measured m_;
    std::size_t n_ = 0;                      // samples so far
    std::array<AxisVector, 4> recent_{};     // the last four positions, by sample index mod 4
    std::array<std::size_t, 2> tracked_{};   // segment of samples i-1 and i (by index mod 2)
    std::size_t k_ = 0;                      // tracking: segment of the newest tracked sample
    double stray_ = 0.0;                     // largest distance of a tracked sample from the path
    double lone_point_ = 0.0;                // a program that never moves: distance from its point
    FrontQueue<Segment> window_;             // segments from window_base_ on
    std::size_t window_base_ = 0;
    std::deque<std::pair<std::size_t, double>> open_;  // corners still taking chords, ascending
    // Axes 0 .. dims_-1 hold every non-zero coordinate seen so far (distances need no more).
    int dims_ = 1;
    // The chords between samples c and c+1 last asked for, by c mod 4 (index: none yet).
    struct Chord {
        static constexpr std::size_t none = static_cast<std::size_t>(-1);
        std::size_t index = none;
        Segment segment;
    };
    std::array<Chord, 4> chords_{};
};

}  // namespace firtp
