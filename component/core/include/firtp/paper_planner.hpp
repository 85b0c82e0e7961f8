// The paper's mode (Sencer et al. 2015): one fixed chain for every block, given as [FIRTP]T1..T4
// or tuned to the machine's modes. Each block is one velocity pulse of its feed (Eq. 5); the next
// pulse starts Td - Tk after it ends (Eq. 11), Tk chosen so the corner stays within the block's
// tolerance (Eq. 13/14, corner.hpp). Causal: a block is scheduled when it arrives, with no
// look-ahead; a block that arrives late only shortens Tk.
//
// Two long blocks (pulses of at least Td) and no axis limits: the closed form. Short blocks, where
// three or more may share a filter window, and machines with axis limits: each candidate
// schedule is checked in closed form on the legs it overlaps (motion_check.hpp) — the limits by
// the sweep, the corners it can still move by their closest approach — with nothing after it (a
// stop is always possible later), so what was checked is what the machine does. Tk is lowered
// by bisection where a check fails; where even a stop fails, the feed.
#pragma once

#include <firtp/corner.hpp>
#include <firtp/fir_chain.hpp>
#include <firtp/motion_check.hpp>
#include <firtp/parameters.hpp>
#include <firtp/report.hpp>
#include <firtp/search.hpp>
#include <firtp/timeline.hpp>
#include <firtp/types.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace firtp {

class PaperPlanner {
public:
    PaperPlanner(const PlannerParameters& parameters, const FirChain& chain, Timeline& timeline, const AxisVector& start);

    // Validated by the caller; queue_full leaves everything as it was; skipped: zero length.
    // invalid_block: the pulse does not fit the servo clock. infeasible: no feed, down to the
    // slowest pulse the clock holds, passes the check (stats().refused).
    Result add(const Block& block);
    void reset(const AxisVector& position);
    const AxisVector& goal() const { return last_.end; }
    const PlannerStats& stats() const { return stats_; }
    bool take_report(CornerReport& report);

private:
    struct Last {
        bool moving = false;                        // a block exists to blend with
        AxisVector end = AxisVector::Zero();
        AxisVector run_delta = AxisVector::Zero();  // incoming pulse: this block and collinear ones joined to it
        double run_tv = 0.0;
        double Tk_in = 0.0;                         // overlap at the corner where the run started
        double feed = 0.0;
        Termination termination = Termination::exact_stop;
        double tolerance = 0.0;
        std::int64_t line = 0;
        std::int64_t end_tick = 0;                  // pulse end, as tick + offset
        double end_offset = 0.0;
    };
    struct Start {
        std::int64_t tick;
        double offset;
        double Tk;  // the overlap this start gives (less than asked when the block came late)
    };
    struct Choice {
        double Tk;
        double feed;
    };
    // A corner the next pulses may still move: its point, tolerance, the leg ending at it (counted
    // since construction) and when its overlap ends.
    struct Corner {
        AxisVector point;
        double epsilon;
        std::uint64_t leg;
        double window_end;  // seconds on the timeline's clock (tick * period)
        double guess;       // where its closest approach is expected, likewise
    };

    // rest: a blended corner's stop; dwell: G4, at rest this long more after a stop (Tk = 0)
    Start schedule(double Tk, std::int64_t now, bool rest = false, double dwell = 0.0) const;
    double latest_overlap(std::int64_t now) const;
    Leg candidate(const AxisVector& delta, double length, double feed, const Start& start, const Block& block) const;
    // Passes when the candidate keeps the limits and every corner it can move (with nothing after
    // it); its margin is the least relative slack of those corners (-1 where a limit breaks).
    search::Probe feasible(const Leg& leg, double corner_epsilon, bool corner_bound);
    std::optional<Choice> search(const AxisVector& delta, double length, double feed, double beta, double epsilon,
                                 const Block& block);
    std::optional<double> feed_for_start(const AxisVector& delta, double length, double feed, const Start& start,
                                         const Block& block);
    void to_timed(const Leg& leg, TimedLeg& out) const;

    PlannerParameters parameters_;
    MachineLimits limits_;
    bool check_limits_ = false;
    const FirChain* chain_;
    Timeline* timeline_;
    Last last_;
    PlannerStats stats_;
    std::uint64_t pushed_ = 0;   // legs pushed since construction
    double pending_dwell_ = 0.0; // dwell of skipped zero-length blocks: the next block's
    std::array<Corner, 16> corners_{};  // recent corners, oldest first
    std::size_t corner_count_ = 0;
    LimitSweep sweep_;
    std::vector<TimedLeg> legs_;  // scratch
    std::array<CornerReport, 64> reports_{};
    std::size_t report_head_ = 0, report_count_ = 0;
};

}  // namespace firtp
