// Offline use of the core: plan a whole program and sample it every servo period.
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/report.hpp>
#include <firtp/types.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace firtp {

class Planner;

struct Trajectory {
    std::vector<AxisState> samples;    // t = 0 at the start point ... last sample at rest at the end
    std::vector<CornerReport> corners; // one per junction, in program order
    AxisVector start = AxisVector::Zero();
    double cycle_time = 0.0;           // time of the last sample
    PlannerStats stats;                // the planner's counts: blocks slowed, crawling
};

// Receives the samples and corner reports in the order the planner produces them.
class TrajectorySink {
public:
    virtual ~TrajectorySink() = default;
    virtual void sample(const AxisState& state) = 0;
    virtual void corner(const CornerReport& report) = 0;
};

// What is left of a streamed plan once the samples went to the sink.
struct StreamedTrajectory {
    std::size_t samples = 0;
    double cycle_time = 0.0;  // time of the last sample
    PlannerStats stats;
};

// Hands a program's blocks over in order, one at a time, as the planner takes them.
class BlockPuller {
public:
    virtual ~BlockPuller() = default;
    virtual bool next(Block& block) = 0;  // false: no more blocks
};

// The blocks of a span in memory, in order (the span must outlive it).
class SpanPuller : public BlockPuller {
public:
    explicit SpanPuller(std::span<const Block> blocks) : blocks_(blocks) {}
    bool next(Block& block) override {
        if (next_ == blocks_.size()) return false;
        block = blocks_[next_++];
        return true;
    }

private:
    std::span<const Block> blocks_;
    std::size_t next_ = 0;
};

// Whether plan_trajectory adds blocks before this period: an eighth of the queue is free, nothing
// waits, or a start is due (it asks whether the blocks known settle it). It adds them with
// Planning::at_update: the path's end, braking to a stop after the last block, is then planned
// and checked once a batch instead of once a block (on a dense path that braking reaches back
// over tens of blocks). The paper's mode plans each block as it comes: whenever there is room.
bool refill_due(const Planner& planner);

// Runs the planner as the servo thread would, blocks arriving in batches as fast as it takes them
// (refill_due), and hands every sample and corner to `sink` as it is made (memory: the planner's
// queue, not the program's duration). Throws std::invalid_argument naming the block's line when a
// block is invalid.
StreamedTrajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                                   std::span<const Block> blocks, TrajectorySink& sink);
// The same, pulling the blocks from `blocks` as the planner's queue takes them (memory: the
// queue, not the program's length).
StreamedTrajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                                   BlockPuller& blocks, TrajectorySink& sink);

// The same, keeping every sample.
Trajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                           std::span<const Block> blocks);

}  // namespace firtp
