// A plain reference planner to compare firtp with: every block on its own rest-to-rest S-curve
// (jerk-limited, so the acceleration is a trapezoid in time; with no jerk limit the velocity is a
// trapezoid), exact stop at every block, the next block at the next servo sample. Nothing is
// tuned to a mode; the limits are the path's share of the axis limits.
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/types.hpp>

#include <span>
#include <vector>

namespace firtp {

// One rest-to-rest move of `length` under speed, acceleration and jerk limits (jerk 0 or infinite:
// not limited), time-optimal: jerk phases, constant acceleration, cruise, mirrored.
class SCurve {
public:
    SCurve(double length, double max_velocity, double max_acceleration, double max_jerk);

    double duration() const { return duration_; }
    double peak_velocity() const { return peak_velocity_; }

    struct State {
        double s = 0.0, v = 0.0, a = 0.0, j = 0.0;
    };
    State at(double t) const;  // clamped to [0, duration]

private:
    struct Segment {
        double start = 0.0, length = 0.0, jerk = 0.0;
        State state;  // at start
    };
    std::array<Segment, 7> segments_{};
    double duration_ = 0.0;
    double peak_velocity_ = 0.0;
};

// Samples the program every `period` from t = 0 at `start`, as Trajectory::samples does: position,
// velocity, acceleration and jerk of every axis, the block's line. Speed: the block's feed, capped
// so each axis keeps limits.axis[i].max_velocity; acceleration and jerk along the path the largest
// each axis allows (0 = not limited; acceleration must be limited on the axes that move).
// Throws std::invalid_argument for a non-positive feed or an axis that moves without an
// acceleration limit.
std::vector<AxisState> plan_exact_stop_scurves(const MachineLimits& limits, double period, const AxisVector& start,
                                               std::span<const Block> blocks);

}  // namespace firtp
