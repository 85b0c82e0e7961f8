#include <firtp/trajectory.hpp>

#include <firtp/planner.hpp>

#include <stdexcept>
#include <string>

namespace firtp {

Trajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                           std::span<const Block> blocks) {
    Planner planner(parameters, start);
    Trajectory trajectory;
    trajectory.start = start;
    std::size_t next = 0;
    for (;;) {
        for (; next < blocks.size(); ++next) {
            const Result result = planner.add(blocks[next]);
            if (result == Result::queue_full) break;
            if (result == Result::invalid_block)
                throw std::invalid_argument("line " + std::to_string(blocks[next].line) + ": " + planner.refusal());
        }
        if (next == blocks.size()) planner.finish();
        AxisState state;
        planner.tick(state);
        trajectory.samples.push_back(state);
        for (CornerReport r; planner.take_report(r);) trajectory.corners.push_back(r);
        if (next == blocks.size() && planner.idle()) break;
    }
    trajectory.cycle_time = trajectory.samples.back().time;
    trajectory.stats = planner.stats();
    return trajectory;
}

}  // namespace firtp
