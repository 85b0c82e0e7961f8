// The random corners of firtp_bench (BM_PlanBlock, BM_Tick), firtp_worst_add and
// firtp_plan_stream --generate corners: each block 2-40 mm from the last in a random direction of
// the first `axes` axes, at 100-300 mm/s (or 250 throughout), 0.05 mm tolerance. The machines
// firtp_bench plans them on, and the ticks between two blocks of the stream.
#pragma once

#include <firtp/parameters.hpp>
#include <firtp/planner.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <cstdint>
#include <random>

namespace firtp::bench {

// "limits": the built-in machine's axes (300 mm/s, 5000 mm/s^2, 1e5 mm/s^3), every move smoothed
// at its limits; otherwise the paper's fixed chain (T 148, 89, 31, 11 ms, `stages` of them).
inline PlannerParameters machine(bool limits, int axes, int stages) {
    PlannerParameters p;
    p.limits.axes = axes;
    for (int a = 0; a < axes; ++a) p.limits.axis[a] = {300.0, 5000.0, 1e5};
    p.queue_capacity = 256;
    if (!limits) {
        p.fixed_chain = true;
        p.limits = MachineLimits{};
        p.filters.stages = stages;
        const double times[] = {0.148, 0.089, 0.031, 0.011};
        for (int i = 0; i < stages; ++i) p.filters.T[i] = times[i];
    }
    return p;
}

class RandomCorners {
public:
    RandomCorners(int axes, bool varying_feed, std::uint64_t seed) : axes_(axes), varying_(varying_feed), rng_(seed) {}
    Block next() {
        AxisVector d = AxisVector::Zero();
        for (int a = 0; a < axes_; ++a) d[a] = unit_(rng_);
        at_ += d.normalized() * length_(rng_);
        Block b;
        b.target = at_;
        b.feed = varying_ ? feed_(rng_) : 250.0;
        b.tolerance = 0.05;
        b.line = ++line_;
        return b;
    }

private:
    int axes_;
    bool varying_;
    std::mt19937_64 rng_;
    std::uniform_real_distribution<double> unit_{-1.0, 1.0}, length_{2.0, 40.0}, feed_{100.0, 300.0};
    AxisVector at_ = AxisVector::Zero();
    std::int64_t line_ = 0;
};

// Ticks until the stream of 64 blocks of look-ahead has room for the next. Blocks that waited
// beyond the window's reach join it at a tick; the ticks that planned (segment plans counted)
// are timed by `now` (ns): their sum and the slowest. Ticks that plan nothing are BM_Tick's.
struct PlanningTicks {
    double total_ns = 0.0, slowest_ns = 0.0;
};
template <class Now>
PlanningTicks tick_until_room(Planner& planner, AxisState& out, Now now) {
    PlanningTicks t;
    while (planner.depth() >= 64 || planner.free() == 0) {
        // (A join's steps plan no segment but one: they count by the blocks joined and the steps.)
        const auto planning = [&] {
            const PlannerStats& s = planner.stats();
            return s.segments_planned + s.rejoined + s.join_steps;
        };
        const std::uint64_t planned = planning();
        const double begin = static_cast<double>(now());
        planner.tick(out);
        const double end = static_cast<double>(now());
        if (planning() == planned) continue;
        t.total_ns += end - begin;
        t.slowest_ns = std::max(t.slowest_ns, end - begin);
    }
    return t;
}

}  // namespace firtp::bench
