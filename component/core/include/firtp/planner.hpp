// firtp's planning core behind one object: blocks in, one commanded axis state per servo period
// out. Every user (firtp plan, the HAL component, the LinuxCNC module firtp_tp) runs the core
// through it; nothing else wires chain, timeline and planner. Real-time after construction: no
// allocation, no locks, no I/O, no exceptions.
//
// Two modes, chosen by the parameters:
//   limit-driven (the default): every velocity change is smoothed at the machine's own limits
//     (kernel.hpp), corners pass at the highest speed their tolerance allows (junction.hpp), and
//     a look-ahead plans speeds so the tool can always stop in time (lookahead.hpp);
//   the paper's fixed chain ([FIRTP]T1..T4 or MODES): one chain for every block and the
//     overlap Tk of Sencer et al. 2015 at each corner (paper_planner.hpp).
// Both write legs to one timeline (timeline.hpp), which the servo period evaluates.
//
//     Planner planner(parameters, start);
//     planner.add(block);              // as blocks come; Result::queue_full: try again later
//     PlannerInput in;                 // feed override, hold, end of the program
//     PlannerOutput out;
//     planner.update(in, out);         // every servo period: Result::working or finished
// examples/api/01_corner.cpp shows it whole.
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

// What a servo period asks of the planner.
struct PlannerInput {
    double rate = 1.0;            // feed override, 0 .. max_rate (1 = as programmed)
    bool hold = false;            // stop on the path as soon as the limits allow (rate 0)
    bool end_of_program = false;  // no more blocks follow for now: the last one ends the motion
};

// What it gives back.
struct PlannerOutput {
    AxisState state;       // the commanded axes at this period
    bool flushed = false;  // an abort came to rest in this period (or was asked while at rest)
};

class Planner {
public:
    // Throws std::invalid_argument for parameters that cannot work (init only).
    Planner(const PlannerParameters& parameters, const AxisVector& start);
    Planner(const Planner&) = delete;
    Planner& operator=(const Planner&) = delete;
    ~Planner();

    // Validates and queues one block: ok, skipped (zero length), queue_full (nothing changes), or
    // refused (nothing changes): invalid_block, absent_axis or infeasible (types.hpp). Planned now
    // or at the next update (Planning); the paper's mode plans now either way.
    Result add(const Block& block, Planning when = Planning::now);
    // Why the last add() refused its block, in words (names the axis of absent_axis).
    const char* refusal() const { return refusal_; }

    // One servo period: applies the input (as set_rate and finish), settles what starts now and
    // writes the state at this period. working while anything moves or waits, else finished.
    Result update(const PlannerInput& in, PlannerOutput& out) noexcept;

    // No more blocks follow for now: the last one ends the motion (update's end_of_program).
    void finish();
    // One servo period without input (update does this after applying its input).
    void tick(AxisState& out);

    // Feed override (0 = hold: stop on the path as soon as the limits allow; 1 = as programmed, up
    // to max_rate). Blocks added after it are planned at it: a caller that learns the rate at the
    // start of a period and adds blocks before update() sets it first (update's is then no change).
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
    // A start is due at the next update and asks whether the blocks known settle it (a caller
    // adding blocks in batches, Planning::at_update, fills the queue first; the paper's mode: no).
    bool start_due() const { return lookahead_ && lookahead_->start_due(); }
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
    // The step that brings `velocity` to rest: the paper's chain, or one step at smoothing_limits.
    Kernel brake_kernel(const AxisVector& velocity) const;

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
