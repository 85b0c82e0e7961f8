// Checks a candidate block against the servo samples it will produce, for paths where several
// blocks share a filter window (short blocks, dense CAM paths, arc chords) or where axis limits
// must hold inside overlaps. Eq. 13/14 assume two blocks per window; here the trajectory itself
// is evaluated.
//
// Principle: the committed blocks' output is known exactly. A candidate (start, feed) is
// feasible when, with no block after it (the stop scenario), every sample from its start until
// the tool rests is within the limits and every corner's closest approach (chords between
// samples) or the distance to the path stays within tolerance. A later block can always start
// after everything settled (Tk = 0), which reproduces the stop scenario, so by induction what
// was checked is what the machine does. Everything is in fixed-size storage sized at
// construction: planning a block costs O(Td / period), whatever the number of blocks in the
// window.
#pragma once

#include <firtp/fir_chain.hpp>
#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <cstdint>
#include <vector>

namespace firtp {

struct Candidate {
    AxisVector delta = AxisVector::Zero();
    double tv = 0.0;
    std::int64_t start_tick = 0;  // pulse start = start_tick * period + start_offset
    double start_offset = 0.0;
};

class SampledWindow {
public:
    SampledWindow(const FirChain& chain, const PlannerParameters& parameters, std::size_t max_corners = 4096);

    // Nothing moving; the tool rests at `position`; samples from `tick` on.
    void reset(const AxisVector& position, std::int64_t tick);

    // The junction at the end of the committed path gets tolerance epsilon (+inf: none) before
    // the next candidate is checked; `bound` says whether the tolerance is checked there.
    void set_corner_tolerance(double epsilon, bool bound);

    // True when the candidate keeps every sample within tolerance and limits (stop scenario).
    // stride > 1 looks at every stride-th sample only (and the last, and after a stop the first,
    // on the junction): a quick search that can miss a limit between its samples; only stride 1
    // decides.
    bool feasible(const Candidate& c, int stride = 1) const;

    // Commits a candidate that was feasible (or a stop): its samples become the committed output.
    void commit(const Candidate& c);

    bool checks_limits() const { return check_limits_; }

private:
    struct Sample {
        AxisVector position, velocity, acceleration, jerk;
    };
    struct Corner {
        AxisVector point;
        double epsilon;
        double best;               // closest approach so far (chords of finalized samples)
        bool bound;
        std::int64_t release_tick; // after this tick nothing can move it (set when known)
        AxisVector segment_end;    // the segment that starts here ends at the next corner
        // Time order, which holds where geometry is ambiguous (a path passing back near itself):
        std::int64_t start_tick;   // the pulse leaving this junction has begun (before: not passed)
        std::int64_t passed_tick;  // the pulse arriving here has filtered out: passed from then on
    };

    // A pass over samples in time order: which junction the tool is at, and the closest
    // approach to it and the next two so far.
    struct Sweep {
        std::size_t cursor;
        double closest[3];
        AxisVector history[3];  // the last three samples, newest first (chords, finite differences)
        int known;              // how many of them are consecutive samples
    };

    const Sample& committed(std::int64_t tick) const;  // output of the committed blocks at a tick
    Sample with(const Candidate& c, std::int64_t tick, const Sample& base) const;
    bool within_limits(const Sample& s) const;
    bool differences_within_limits(const Sweep& w, const AxisVector& p) const;  // as a drive sees them
    double segment_distance(const AxisVector& p, std::size_t i, const AxisVector& candidate_delta) const;
    double path_distance(const AxisVector& p, std::size_t cursor, const AxisVector& candidate_delta) const;
    Sweep start_sweep() const;
    // Takes the sample at p; false when a junction the tool passed was not approached within its
    // tolerance. With `keep`, passed junctions keep their closest approach for good.
    // The sample at `tick`; the candidate's segment leaves the last junction (candidate_delta,
    // first sample candidate_start).
    bool visit(Sweep& w, const AxisVector& p, std::int64_t tick, bool keep, const AxisVector& candidate_delta,
               std::int64_t candidate_start);
    bool check_sample(Sweep& w, const Sample& s, std::int64_t tick, double contour_epsilon, const Candidate& c,
                      std::int64_t candidate_start, bool consecutive) const;
    void sweep_tail();  // restarts prefix_ from the finalized state
    const Sweep& prefix(std::size_t i) const;  // extends prefix_ to entry i
    void release_passed_corners(std::int64_t tick);  // junctions no sample from tick on can approach
    Corner& corner(std::size_t i) { return corners_[(corner_head_ + i) % corners_.size()]; }
    const Corner& corner(std::size_t i) const { return corners_[(corner_head_ + i) % corners_.size()]; }

    const FirChain* chain_;
    double period_;
    ToleranceMeaning meaning_;
    MachineLimits limits_;
    bool check_limits_ = false;
    int axes_;                         // geometry over the machine's axes only
    std::int64_t window_ticks_;        // Td / period, rounded up, plus margin

    std::vector<Sample> tail_;         // committed output for ticks tail_tick_ .. tail_tick_ + size
    mutable std::vector<Sweep> prefix_;  // sweep state before each tail tick (candidates start there),
    mutable std::size_t prefix_valid_ = 0;  // filled on demand: entries [0, prefix_valid_)
    std::int64_t tail_tick_ = 0;
    AxisVector rest_ = AxisVector::Zero();  // where the committed blocks end
    Sample at_rest_;                   // the committed output after the tail
    AxisVector finalized_history_[3] = {AxisVector::Zero(), AxisVector::Zero(), AxisVector::Zero()};
    int finalized_known_ = 0;

    std::vector<Corner> corners_;      // ring: junctions that samples can still approach
    std::size_t corner_head_ = 0;
    std::size_t corner_count_ = 0;
    std::size_t cursor_ = 0;           // the junction the finalized samples are at
};

}  // namespace firtp
