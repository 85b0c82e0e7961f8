// Accepts blocks one at a time and schedules their velocity pulses: each new block starts
// Td - Tk after the previous pulse ended (Eq. 11), Tk chosen so the corner stays within the
// block's tolerance. Causal: a block is scheduled when it arrives, with no look-ahead, so a
// stream can start moving at once; a block that arrives late only shortens Tk.
//
// Two long blocks (pulses of at least Td) and no axis limits: Eq. 13/14 (CornerModel). Short
// blocks, where three or more may share a filter window, and machines with axis limits: the
// candidate schedule is checked on its servo samples (SampledWindow), overlaps included.
//
// Neighbouring corners never share a filter window: Tk_(i-1) + Tk_i <= Tv_i + Td - period (notes,
// with one servo period to spare for the sampled error bound), kept by giving each corner at most
// what the previous corner left of the incoming block, and at most half of the outgoing block. Collinear blocks of equal feed join into one pulse (Tk = Td) when
// the previous corner's overlap lies inside the run, so the join cannot change that corner. A
// junction where the path goes straight on is not a corner: its tolerance bounds nothing, and
// the path there stays within the neighbouring corners' tolerances.
#pragma once

#include <firtp/corner.hpp>
#include <firtp/fir_chain.hpp>
#include <firtp/interpolator.hpp>
#include <firtp/parameters.hpp>
#include <firtp/sampled_window.hpp>
#include <firtp/types.hpp>

#include <cstdint>
#include <optional>

namespace firtp {

// What the planner decided at the junction between two blocks.
struct CornerReport {
    std::int64_t line = 0;                  // line of the block that ends at the corner
    AxisVector point = AxisVector::Zero();  // programmed corner point
    double beta = 0.0;                      // change of direction, rad
    double tk = 0.0;                        // overlap used, s
    double tk_tolerance = 0.0;              // overlap the tolerance alone allows, s
    double epsilon = 0.0;                   // tolerance asked for (+inf: none)
    double predicted_error = 0.0;           // continuous corner error at tk (per the tolerance meaning)
    bool exact_stop = false;
};

class Planner {
public:
    Planner(const PlannerParameters& parameters, const FirChain& chain, const AxisVector& start);

    // Validates, plans and queues one block. Result::queue_full leaves everything as it was.
    // A zero-length block is accepted and skipped. When the block forms a corner with the
    // previous one, *corner (if given) is filled and *has_corner set. Result::invalid_block also
    // when no feed, down to the slowest pulse the clock holds, passes the window check (a stop
    // slow enough always does, unless the committed samples themselves fail it): nothing is
    // committed unchecked, and the tool rests at the previous block's end (Stats::refused).
    Result add(const Block& block, Interpolator& out, CornerReport* corner = nullptr,
               bool* has_corner = nullptr);

    // Blocks counted since construction.
    struct Stats {
        std::uint64_t slowed = 0;    // planned below their feed (window check: tolerance or limits)
        std::uint64_t crawling = 0;  // ... below 0.1 % of it
        std::uint64_t refused = 0;   // no feed passed the check (see add)
    };
    const Stats& stats() const { return stats_; }

    // After the interpolator was reset or flushed: plan from rest at `position` (filter-clock tick).
    void reset(const AxisVector& position, std::int64_t tick = 0);

    const AxisVector& goal() const { return last_.end; }

private:
    struct Last {
        bool moving = false;                    // a block exists to blend with
        AxisVector end = AxisVector::Zero();
        AxisVector run_delta = AxisVector::Zero();  // incoming pulse: this block and collinear ones joined to it
        double run_tv = 0.0;
        double tk_in = 0.0;                     // overlap at the corner where the run started
        double feed = 0.0;
        Termination termination = Termination::exact_stop;
        double tolerance = 0.0;
        std::int64_t line = 0;
        std::int64_t end_tick = 0;              // pulse end, as tick + offset
        double end_offset = 0.0;
    };

    struct Start {
        std::int64_t tick;
        double offset;
        double tk;   // the overlap this start gives (less than asked when the block came late)
    };
    struct Choice {
        double tk;
        double feed;
    };

    Start schedule(double tk, std::int64_t now) const;
    double latest_overlap(std::int64_t now) const;
    // None: no feed passes (add refuses the block).
    std::optional<Choice> search_window(const AxisVector& delta, double length, double feed, double beta,
                                        double epsilon, std::int64_t now) const;
    // The highest feed, up to `feed`, at which the block starting at `start` passes the window
    // check (from rest or after a stop, where only the feed can keep the limits); none: no feed.
    std::optional<double> feed_for_start(const AxisVector& delta, double length, double feed, const Start& start) const;

    PlannerParameters parameters_;
    const FirChain* chain_;
    SampledWindow window_;
    Last last_;
    Stats stats_;
};

}  // namespace firtp
