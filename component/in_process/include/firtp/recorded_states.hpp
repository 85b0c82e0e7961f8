// The trajectory as it travelled over LCM (FIRTP_AXIS_STATE), laid out as `firtp plan` samples it.
#pragma once

#include <firtp/types.hpp>
#include <firtp_lcm/axis_state_t.hpp>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace firtp {

// First sample: the period the first block started in (t = 0, at the start point); last sample:
// the first period at rest after the motion. Jerk is not sent: it is the first difference of the
// received accelerations. Messages go in one at a time, in arrival order; each sample goes out as
// soon as it is known not to belong to the final rest. Memory: the previous message and the rest
// since the motion last stopped with no line, as runs of equal samples (not one per period).
class AxisStateSamples {
public:
    AxisStateSamples(double period, std::function<void(const AxisState&)> out);

    void add(const firtp_lcm::axis_state_t& message);
    // The end: the rest held back is dropped but for its first sample. Throws std::runtime_error
    // when no block ever moved.
    void finish();
    // The end of a program without motion (a subroutine file): its one sample is the newest state
    // at rest, at time 0, as a plan of it has. Throws std::runtime_error when no state came.
    void finish_at_rest();
    std::size_t count() const { return count_; }  // samples given out

private:
    struct Run {  // `repeats` more samples equal to `sample` but for their ticks, one period apart
        std::int64_t tick = 0;
        AxisState sample;
        std::size_t repeats = 0;
    };
    void take(std::int64_t tick, const AxisState& sample);
    void emit(const AxisState& sample);
    void release_held();
    double time_of(std::int64_t tick) const { return static_cast<double>(tick - tick0_) * period_; }

    double period_;
    std::function<void(const AxisState&)> out_;
    std::optional<firtp_lcm::axis_state_t> before_;  // the newest message before any line showed
    bool started_ = false;
    std::int64_t tick0_ = 0;
    std::optional<AxisState> previous_;  // the newest sample made, given out or held
    std::deque<Run> held_;               // samples the final rest would drop, if it ended now
    std::size_t count_ = 0;
};

// The same for a whole recording.
std::vector<AxisState> samples_from_axis_states(const std::vector<firtp_lcm::axis_state_t>& states, double period);

}  // namespace firtp
