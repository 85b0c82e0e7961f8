// plan_trajectory's loop (trajectory.cpp), keeping the planner's counts (Planner::Stats).
#pragma once

#include <firtp/interpolator.hpp>
#include <firtp/planner.hpp>
#include <firtp/time_scale.hpp>
#include <firtp/trajectory.hpp>

#include <span>

namespace firtp::test {

struct CountedPlan {
    Trajectory trajectory;
    Planner::Stats stats;
    bool complete = true;  // false: a block was refused (Result::invalid_block); planning stopped there
};

inline CountedPlan plan_counted(const PlannerParameters& parameters, const AxisVector& start,
                                std::span<const Block> blocks) {
    const FirChain chain(parameters.filters);
    Interpolator interpolator(chain, parameters.period, parameters.queue_capacity, start, rate_limits(parameters));
    Planner planner(parameters, chain, start);
    CountedPlan plan;
    plan.trajectory.start = start;
    std::size_t next = 0;
    for (;;) {
        for (; next < blocks.size(); ++next) {
            CornerReport corner;
            bool has_corner = false;
            const Result result = planner.add(blocks[next], interpolator, &corner, &has_corner);
            if (result == Result::queue_full) break;
            if (result == Result::invalid_block) {
                plan.complete = false;
                plan.stats = planner.stats();
                return plan;
            }
            if (has_corner) plan.trajectory.corners.push_back(corner);
        }
        AxisState state;
        interpolator.tick(state);
        plan.trajectory.samples.push_back(state);
        if (next == blocks.size() && interpolator.idle()) break;
    }
    plan.trajectory.cycle_time = plan.trajectory.samples.back().time;
    plan.stats = planner.stats();
    return plan;
}

}  // namespace firtp::test
