#include <firtp/trajectory.hpp>

#include <firtp/planner.hpp>

#include <stdexcept>
#include <string>

namespace firtp {

StreamedTrajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                                   std::span<const Block> blocks, TrajectorySink& sink) {
    Planner planner(parameters, start);
    StreamedTrajectory out;
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
        ++out.samples;
        out.cycle_time = state.time;
        sink.sample(state);
        for (CornerReport r; planner.take_report(r);) sink.corner(r);
        if (next == blocks.size() && planner.idle()) break;
    }
    out.stats = planner.stats();
    return out;
}

Trajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                           std::span<const Block> blocks) {
    struct Keep : TrajectorySink {
        Trajectory& t;
        explicit Keep(Trajectory& into) : t(into) {}
        void sample(const AxisState& state) override { t.samples.push_back(state); }
        void corner(const CornerReport& report) override { t.corners.push_back(report); }
    };
    Trajectory trajectory;
    trajectory.start = start;
    Keep keep(trajectory);
    const StreamedTrajectory streamed = plan_trajectory(parameters, start, blocks, keep);
    trajectory.cycle_time = streamed.cycle_time;
    trajectory.stats = streamed.stats;
    return trajectory;
}

}  // namespace firtp
