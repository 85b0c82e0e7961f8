// examples/polygon360.ngc's chords, round and round without end: a circle of R20 in 0.35 mm
// chords, G64 P0.5, at `feed` (the program's F15000 is 250 mm/s). The dense path of the
// worst-case benchmarks (firtp_worst_override --chords, firtp_worst_period): the motion's stop
// spans the most blocks there.
#pragma once

#include <firtp/types.hpp>

#include <cmath>
#include <cstdint>

namespace firtp::bench {

class Chords {
public:
    explicit Chords(double feed = 300.0) : feed_(feed) {}
    Block next() {
        ++count_;
        const double angle = 2.0 * M_PI * static_cast<double>(count_) / 360.0;
        Block b;
        b.target = AxisVector::Zero();
        b.target[0] = 20.0 * std::cos(angle) - 20.0;
        b.target[1] = 20.0 * std::sin(angle);
        b.feed = feed_;
        b.tolerance = 0.5;
        b.line = count_;
        return b;
    }
    std::int64_t count() const { return count_; }

private:
    double feed_;
    std::int64_t count_ = 0;
};

}  // namespace firtp::bench
