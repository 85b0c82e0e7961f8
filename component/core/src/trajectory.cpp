#include <firtp/trajectory.hpp>

#include <firtp/interpolator.hpp>

#include <stdexcept>
#include <string>

namespace firtp {

Trajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                           std::span<const Block> blocks) {
    const FirChain chain(parameters.filters);
    Interpolator interpolator(chain, parameters.period, parameters.queue_capacity, start, rate_limits(parameters));
    Planner planner(parameters, chain, start);

    Trajectory trajectory;
    trajectory.start = start;
    std::size_t next = 0;
    for (;;) {
        for (; next < blocks.size(); ++next) {
            CornerReport corner;
            bool has_corner = false;
            const std::uint64_t refused = planner.stats().refused;
            const Result result = planner.add(blocks[next], interpolator, &corner, &has_corner);
            if (result == Result::queue_full) break;
            if (result == Result::invalid_block)
                throw std::invalid_argument(
                    "line " + std::to_string(blocks[next].line) +
                    (planner.stats().refused > refused
                         ? ": no feed, down to a stop, keeps this block within its tolerance and the axis limits"
                         : ": invalid block (non-finite target, feed <= 0 or bad tolerance)"));
            if (has_corner) trajectory.corners.push_back(corner);
        }
        AxisState state;
        interpolator.tick(state);
        trajectory.samples.push_back(state);
        if (next == blocks.size() && interpolator.idle()) break;
    }
    trajectory.cycle_time = trajectory.samples.back().time;
    trajectory.stats = planner.stats();
    return trajectory;
}

}  // namespace firtp
