#include <firtp/trajectory.hpp>

#include <firtp/planner.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace firtp {

bool refill_due(const Planner& planner) {
    if (planner.fixed_chain()) return planner.free() > 0;
    const std::size_t batch = std::max<std::size_t>(1, planner.parameters().queue_capacity / 8);
    return planner.free() >= batch || planner.idle() || planner.start_due();
}

StreamedTrajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                                   BlockPuller& blocks, TrajectorySink& sink) {
    Planner planner(parameters, start);
    StreamedTrajectory out;
    PlannerInput input;
    PlannerOutput period;
    Block block;
    bool pending = blocks.next(block);  // taken from the source, not yet by the planner
    for (Result motion = Result::working; motion == Result::working || pending;) {
        for (bool room = refill_due(planner); pending && room; pending = blocks.next(block)) {
            const Result result = planner.add(block, Planning::at_update);
            if (result == Result::queue_full) break;
            if (refused(result))
                throw std::invalid_argument("line " + std::to_string(block.line) + ": " + planner.refusal());
        }
        input.end_of_program = !pending;
        motion = planner.update(input, period);
        ++out.samples;
        out.cycle_time = period.state.time;
        sink.sample(period.state);
        for (CornerReport r; planner.take_report(r);) sink.corner(r);
    }
    out.stats = planner.stats();
    return out;
}

StreamedTrajectory plan_trajectory(const PlannerParameters& parameters, const AxisVector& start,
                                   std::span<const Block> blocks, TrajectorySink& sink) {
    SpanPuller source(blocks);
    return plan_trajectory(parameters, start, source, sink);
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
