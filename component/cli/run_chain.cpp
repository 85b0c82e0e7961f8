#include "run_chain.hpp"

#include "spooled_feed.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace firtp::cli {

namespace {

host::HostOptions receiving(host::HostOptions options, AxisStateSamples& samples) {
    options.on_axis_state = [&samples](const firtp_lcm::axis_state_t& m) { samples.add(m); };
    return options;
}

}  // namespace

RunChain::RunChain(lcm::LCM& lcm, InProcessComponent& component, const PlanRun& run, host::HostOptions host_options,
                   std::function<void(const AxisState&)> received)
    : lcm_(lcm),
      component_(component),
      period_(run.parameters.period),
      moves_(run.blocks > 0),
      samples_(run.parameters.period, std::move(received)),
      host_(lcm, spooled_feed(run.spool, run.program.events), receiving(std::move(host_options), samples_)),
      progress_("run", run.blocks) {}

// One servo period a round: the host publishes, LCM delivers, the component runs, the bridge
// publishes axis state and status for the host's next round.
void RunChain::run_until(std::size_t samples, std::size_t periods) {
    for (; periods_ < periods && running() && samples_.count() < samples; ++periods_) {
        result_ = host_.step();  // the round ends as the others even when this says done
        component_period();
        progress_.update(static_cast<std::size_t>(host_.statistics().blocks_published),
                         static_cast<double>(periods_) * period_);
    }
}

void RunChain::finish() {
    if (finished_) return;
    finished_ = true;
    progress_.clear();
    if (result_ != host::Result::done)
        throw std::runtime_error(cat("run: the program did not complete (", host::to_string(result_), "): ",
                                     host_.error()));
    if (moves_) return samples_.finish();
    // Nothing to send: a period of the component for its state at rest (and one to deliver it).
    for (int i = 0; i < 2; ++i) component_period();
    samples_.finish_at_rest();
}

void RunChain::component_period() {
    while (lcm_.handleTimeout(0) > 0) {
    }
    component_.step();
    component_.poll();
}

void PlanDifference::add(const AxisVector& x, std::deque<AxisVector>& mine, std::deque<AxisVector>& theirs,
                         bool theirs_done) {
    if (theirs_done) return;  // no partner will come
    if (theirs.empty()) return mine.push_back(x);
    largest_ = std::max(largest_, (x - theirs.front()).norm());
    theirs.pop_front();
}

}  // namespace firtp::cli
