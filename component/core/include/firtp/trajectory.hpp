// Offline use of the core: plan a whole program and sample it every servo period.
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/report.hpp>
#include <firtp/types.hpp>

#include <span>
#include <vector>

namespace firtp {

struct Trajectory {
    std::vector<AxisState> samples;    // t = 0 at the start point ... last sample at rest at the end
    std::vector<CornerReport> corners; // one per junction, in program order
    AxisVector start = AxisVector::Zero();
    double cycle_time = 0.0;           // time of the last sample
    PlannerStats stats;                // the planner's counts: blocks slowed, crawling
};

// Runs the planner as the servo thread would, blocks arriving as fast as it takes them; throws
// std::invalid_argument naming the block's line when a block is invalid.
Trajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                           std::span<const Block> blocks);

}  // namespace firtp
