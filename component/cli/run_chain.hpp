// `firtp run`'s chain in this process, a servo period at a time: the host streams the spooled
// program over LCM to the component, whose axis states come back over LCM and go on as samples
// (AxisStateSamples) the moment they are known. Stepped only as far as the caller needs samples,
// so that nothing of the program or of its duration is kept on either side.
#pragma once

#include "plan_run.hpp"
#include "progress_line.hpp"

#include <firtp/host.hpp>
#include <firtp/in_process_component.hpp>
#include <firtp/recorded_states.hpp>

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>

namespace firtp::cli {

class RunChain {
public:
    // received: each received sample, in order. host_options: with this class's on_axis_state.
    RunChain(lcm::LCM& lcm, InProcessComponent& component, const PlanRun& run, host::HostOptions host_options,
             std::function<void(const AxisState&)> received);

    // Servo periods until `samples` samples were received, the host stops running, or `periods`
    // periods have run in all.
    void run_until(std::size_t samples, std::size_t periods);
    bool running() const { return result_ == host::Result::running; }
    // Once the host is no longer running, or no more periods are allowed: throws
    // std::runtime_error unless the program completed; the last samples go out.
    void finish();

    std::size_t received() const { return samples_.count(); }
    const host::Host& host() const { return host_; }

private:
    void component_period();  // LCM delivered, then one servo period of the component and its bridge
    lcm::LCM& lcm_;
    InProcessComponent& component_;
    double period_;
    bool moves_;  // the program has blocks: the states must show one moving (plan samples no motion too)
    AxisStateSamples samples_;
    host::Host host_;
    ProgressLine progress_;
    host::Result result_ = host::Result::running;
    std::size_t periods_ = 0;
    bool finished_ = false;
};

// The largest distance between the planned and the received sample of the same index, each side
// given one sample at a time; holds only the samples one side is ahead by.
class PlanDifference {
public:
    void planned(const AxisVector& p) { add(p, planned_, received_, received_done_); }
    void received(const AxisVector& r) { add(r, received_, planned_, planned_done_); }
    void planned_done() { planned_done_ = true, received_.clear(); }
    void received_done() { received_done_ = true, planned_.clear(); }
    double largest() const { return largest_; }

private:
    void add(const AxisVector& x, std::deque<AxisVector>& mine, std::deque<AxisVector>& theirs, bool theirs_done);

    std::deque<AxisVector> planned_, received_;  // waiting for the other side's
    bool planned_done_ = false, received_done_ = false;
    double largest_ = 0.0;
};

}  // namespace firtp::cli
