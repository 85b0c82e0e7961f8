// The random moves of the worst-case benchmarks (firtp_worst_tick, firtp_worst_override): 0.05-40 mm
// (log-uniform, so short blocks overlap in the filter window), 50-300 mm/s, 0.01-0.1 mm
// tolerances, every 50th an exact stop, inside a 1 m box.
#pragma once

#include <firtp/types.hpp>

#include <cmath>
#include <cstdint>
#include <random>

namespace firtp::bench {

class RandomMoves {
public:
    RandomMoves(int axes, std::uint64_t seed) : axes_(axes), rng_(seed) {}

    Block next() {
        Block b;
        AxisVector d = AxisVector::Zero();
        for (int a = 0; a < axes_; ++a) d[a] = unit_(rng_);
        if (d.norm() < 1e-6) d[0] = 1.0;
        const double length = std::exp(log_length_(rng_));
        at_ += d.normalized() * length;
        // Stay inside a 1 m box: reflect the move's direction back towards the origin.
        for (int a = 0; a < axes_; ++a)
            if (std::abs(at_[a]) > 500.0) at_[a] = std::copysign(500.0, at_[a]) - (at_[a] - std::copysign(500.0, at_[a]));
        b.target = at_;
        b.feed = feed_(rng_);
        b.tolerance = tolerance_(rng_);
        b.termination = ++count_ % 50 == 0 ? Termination::exact_stop : Termination::blend;
        b.line = count_;
        return b;
    }
    std::int64_t count() const { return count_; }

private:
    int axes_;
    std::mt19937_64 rng_;
    std::uniform_real_distribution<double> unit_{-1.0, 1.0};
    std::uniform_real_distribution<double> log_length_{std::log(0.05), std::log(40.0)};
    std::uniform_real_distribution<double> feed_{50.0, 300.0};
    std::uniform_real_distribution<double> tolerance_{0.01, 0.1};
    AxisVector at_ = AxisVector::Zero();
    std::int64_t count_ = 0;
};

}  // namespace firtp::bench
