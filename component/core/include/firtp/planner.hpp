// firtp's planning core behind one object: blocks in, one commanded axis state per servo period
// out. Real-time after construction: no allocation, no locks, no I/O, no exceptions.
//
// Two modes, chosen by the parameters:
//   limit-driven (the default): every velocity change is smoothed at the machine's own limits
//     (kernel.hpp), corners pass at the highest speed their tolerance allows (junction.hpp), and
//     a look-ahead plans speeds so the tool can always stop in time (lookahead.hpp);
//   the paper's fixed chain ([FIRTP]T1..T4 or MODES): one chain for every block and the
//     overlap Tk of Sencer et al. 2015 at each corner (paper_planner.hpp).
// Both write legs to one timeline (timeline.hpp), which the servo tick evaluates.
//
//     Planner planner(parameters, start);
//     planner.add(block);          // as blocks come; Result::queue_full: try again later
//     planner.finish();            // the program ends here (or the stream stalled)
//     planner.tick(state);         // every servo period
#pragma once

#include <firtp/fir_chain.hpp>
#include <firtp/lookahead.hpp>
#include <firtp/paper_planner.hpp>
#include <firtp/parameters.hpp>
#include <firtp/report.hpp>
#include <firtp/timeline.hpp>
#include <firtp/types.hpp>

#include <cstdint>
#include <memory>

namespace firtp {

class Planner {
public:
    // Throws std::invalid_argument for parameters that cannot work (init only).
    Planner(const PlannerParameters& parameters, const AxisVector& start);
    Planner(const Planner&) = delete;
    Planner& operator=(const Planner&) = delete;
    ~Planner();

    // Validates and queues one block: invalid_block for a NaN, an infinite or non-positive feed
    // or a bad tolerance (nothing changes), and in the paper's mode when no feed passes the check
    // (stats().refused); queue_full leaves everything as it was. A zero-length block is skipped.
    Result add(const Block& block);
    // Why the last add() returned invalid_block, in words.
    const char* refusal() const { return refusal_; }
    // No more blocks follow for now: the last one ends the motion.
    void finish();
    // One servo period: settle what starts now, then the state at this period.
    void tick(AxisState& out);

    // Feed override (0 = hold: stop on the path as soon as the limits allow; 1 = as programmed, up
    // to max_rate).
    void set_rate(double rate);
    // Stop on the path, then drop everything; take_flushed() says when it came to rest.
    void abort();
    bool aborting() const { return aborting_; }
    bool take_flushed();
    // Drop everything now and rest at `position` (drives off, a restart).
    void reset(const AxisVector& position);
    // The axes are at `position` moving at `velocity` (found so at a start): continue from there
    // and stop within the limits (one velocity step, braking.hpp); rest at braking_rest().
    void brake_from(const AxisVector& position, const AxisVector& velocity);
    AxisVector braking_rest(const AxisVector& position, const AxisVector& velocity) const;

    bool idle() const;                 // nothing waits, nothing moves
    // Blocks that move (zero-length ones are skipped) accepted, and of those finished, since the
    // last reset or abort.
    std::uint64_t accepted() const { return accepted_; }
    std::uint64_t finished() const { return timeline_.blocks_retired() - finished_base_; }
    std::size_t depth() const;         // blocks accepted and not finished, at most
    std::size_t free() const;          // blocks add() takes now without queue_full
    std::int64_t current_line() const { return timeline_.current_line(); }
    const AxisVector& goal() const;    // end of the last block accepted
    const AxisVector& rest_position() const { return timeline_.rest_position(); }
    std::int64_t ticks() const { return timeline_.ticks(); }
    double period() const { return parameters_.period; }
    const PlannerParameters& parameters() const { return parameters_; }
    bool fixed_chain() const { return paper_ != nullptr; }
    const FirChain& chain() const { return chain_; }  // the paper's mode
    const TimeScale& time_scale() const { return timeline_.time_scale(); }  // the paper's mode: its clock
    const PlannerStats& stats() const;
    // The next corner report (the paper's mode: as blocks are added; else as corners start).
    bool take_report(CornerReport& report);

private:
    PlannerParameters parameters_;
    FirChain chain_;
    Timeline timeline_;
    std::unique_ptr<Lookahead> lookahead_;
    std::unique_ptr<PaperPlanner> paper_;
    double rate_ = 1.0;  // asked for by set_rate (an abort stops regardless)
    bool aborting_ = false;
    bool flushed_ = false;
    const char* refusal_ = "";
    std::uint64_t accepted_ = 0;
    std::uint64_t finished_base_ = 0;
};

}  // namespace firtp
