// A program run through the planner with feed override events at given ticks, as the limit
// suites run it: blocks added as the queue takes them, finish() once all are in, one sample per
// period.
#pragma once

#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace firtp::test {

struct RateRun {
    std::vector<AxisState> samples;
    std::vector<AxisVector> points{AxisVector::Zero()};  // the start and each block's target, as added
    double longest_stop = 0.0;  // s, from a hold or an abort to rest
    bool aborted = false;
    bool ended = false;  // at rest with everything run (or flushed after the abort) within the ticks given
    PlannerStats stats;  // the planner's, at the end
};

// Events (tick, rate): 0 holds, a rate again resumes, < 0 aborts. At most `max_ticks` periods;
// at most `per_period` blocks added before each (as many as the window takes by default).
inline RateRun run_with_rates(const PlannerParameters& p, const std::vector<Block>& blocks,
                              const std::vector<std::pair<int, double>>& events, std::int64_t max_ticks = 20'000'000,
                              std::size_t per_period = static_cast<std::size_t>(-1)) {
    Planner planner(p, AxisVector::Zero());
    RateRun r;
    std::size_t next = 0, event = 0;
    int stopping_since = -1;
    for (int k = 0; k < max_ticks; ++k) {
        for (std::size_t added = 0; next < blocks.size() && added < per_period; ++next, ++added) {
            const Result result = planner.add(blocks[next]);
            if (result == Result::queue_full) break;
            EXPECT_TRUE(result == Result::ok || result == Result::skipped) << static_cast<int>(result);
            r.points.push_back(blocks[next].target);
        }
        if (next == blocks.size()) planner.finish();
        for (; event < events.size() && events[event].first == k; ++event) {
            if (events[event].second < 0.0) {
                planner.abort();
                r.aborted = true;
                if (stopping_since < 0) stopping_since = k;
                continue;
            }
            planner.set_rate(events[event].second);
            if (events[event].second == 0.0 && stopping_since < 0) stopping_since = k;
            if (events[event].second > 0.0 && !r.aborted) stopping_since = -1;
        }
        AxisState s;
        planner.tick(s);
        r.samples.push_back(s);
        if (stopping_since >= 0 && s.velocity.isZero(0.0) && s.acceleration.isZero(0.0)) {
            r.longest_stop = std::max(r.longest_stop, (k - stopping_since) * p.period);
            stopping_since = -1;
        }
        if ((r.aborted && planner.take_flushed()) || (next == blocks.size() && planner.idle() && event == events.size())) {
            r.ended = true;
            break;
        }
    }
    r.stats = planner.stats();
    return r;
}

}  // namespace firtp::test
