// What the plot draws of the samples, in memory bounded whatever the program's duration: a
// min/max decimation of the path and of the time series (every bucket of consecutive samples
// keeps its first sample and the ones holding each column's extremes, so peaks still show), and
// the samples near the corners with the largest measured errors (the zooms).
#pragma once

#include <firtp/report.hpp>
#include <firtp/types.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <deque>
#include <vector>

namespace firtp::cli {

// Rows of C numbers, decimated to at most max_buckets buckets of 2^k consecutive rows. While there
// are no more rows than buckets, every row is kept.
template <std::size_t C>
class MinMaxDecimation {
public:
    using Row = std::array<double, C>;

    explicit MinMaxDecimation(std::size_t max_buckets) : max_buckets_(max_buckets + max_buckets % 2) {}

    void add(const Row& row) {
        const Entry e{count_++, row};
        last_ = e;
        if (e.index / size_ >= max_buckets_) merge();
        if (e.index / size_ == buckets_.size()) {
            buckets_.push_back({e, {}, {}});
            buckets_.back().low.fill(e);
            buckets_.back().high.fill(e);
            return;
        }
        Bucket& b = buckets_.back();
        for (std::size_t c = 0; c < C; ++c) {
            if (row[c] < b.low[c].row[c]) b.low[c] = e;
            if (row[c] > b.high[c].row[c]) b.high[c] = e;
        }
    }

    // The kept rows in order, the last row included.
    std::vector<Row> rows() const {
        std::vector<Row> out;
        std::size_t previous = 0;
        bool any = false;
        for (const Bucket& b : buckets_) {
            std::vector<const Entry*> kept{&b.first};
            for (std::size_t c = 0; c < C; ++c) kept.push_back(&b.low[c]), kept.push_back(&b.high[c]);
            std::sort(kept.begin(), kept.end(), [](const Entry* x, const Entry* y) { return x->index < y->index; });
            for (const Entry* e : kept)
                if (!any || e->index != previous) out.push_back(e->row), previous = e->index, any = true;
        }
        if (any && last_.index != previous) out.push_back(last_.row);
        return out;
    }

    std::size_t count() const { return count_; }

private:
    struct Entry {
        std::size_t index = 0;
        Row row{};
    };
    struct Bucket {
        Entry first;
        std::array<Entry, C> low, high;
    };

    // Pairs of buckets into one: twice the rows a bucket.
    void merge() {
        for (std::size_t i = 0; i < buckets_.size() / 2; ++i) {
            Bucket a = buckets_[2 * i];
            const Bucket& b = buckets_[2 * i + 1];
            for (std::size_t c = 0; c < C; ++c) {
                if (b.low[c].row[c] < a.low[c].row[c]) a.low[c] = b.low[c];
                if (b.high[c].row[c] > a.high[c].row[c]) a.high[c] = b.high[c];
            }
            buckets_[i] = a;
        }
        buckets_.resize(buckets_.size() / 2);
        size_ *= 2;
    }

    std::size_t max_buckets_;
    std::size_t size_ = 1;  // rows a bucket
    std::size_t count_ = 0;
    Entry last_;
    std::vector<Bucket> buckets_;
};

// Samples near one zoomed corner; NaN rows split runs that leave the window.
struct ZoomSamples {
    std::size_t corner = 0;   // index into the corner reports
    double error = 0.0;       // measured
    Eigen::Vector2d centre;   // the corner point
    double half_width = 0.0;  // mm, of the zoom window
    std::vector<Eigen::Vector2d> xy;
    bool inside = false;      // the last sample seen was in the window
};

class PlotSamples {
public:
    PlotSamples();

    void add(const AxisState& s);
    // A corner's measured error, when both it and its report are known (in any order).
    void corner_error(std::size_t index, double error, const CornerReport& report);

    MinMaxDecimation<2> path;  // x y
    MinMaxDecimation<5> time;  // t feed ax ay az
    Eigen::Vector2d low, high; // XY extent of the samples
    bool any = false;
    double max_feed = 0.0;
    double max_acceleration = 0.0;  // over X Y Z
    std::vector<ZoomSamples> zooms; // up to max_zooms, by index

private:
    std::deque<Eigen::Vector2d> recent_;  // the last samples, to fill a zoom chosen after they passed
};

// How the plot sizes a corner's zoom window (half width, mm) and which corners qualify.
double zoom_half_width(const CornerReport& c, double error);
bool zoomable(const CornerReport& c);

}  // namespace firtp::cli
