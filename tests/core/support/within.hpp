// A run measured whole on its samples: the limits, also in finite differences, the blended
// corners within their tolerance, the end exact and at rest.
#pragma once

#include "rate_run.hpp"
#include "sampled_limits.hpp"

#include <firtp/measure.hpp>
#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace firtp::test {

// A program whose path never meets itself, run whole: the limits, also in finite differences,
// every corner within its tolerance once, the end exact and at rest.
inline void expect_within(const RateRun& r, const std::vector<Block>& program, const PlannerParameters& p) {
    std::vector<AxisVector> points{AxisVector::Zero()};
    for (const Block& b : program) points.push_back(b.target);
    const Measured m = measure(r.samples, points, p.period);
    ASSERT_TRUE(r.ended);
    ASSERT_TRUE(m.finite);
    ASSERT_EQ(beyond_limits(r.samples, m, p), "");
    ASSERT_EQ(m.corner_errors.size(), program.size() - 1);  // each corner passed once
    for (std::size_t i = 0; i < m.corner_errors.size(); ++i)
        EXPECT_LE(m.corner_errors[i], program[i].tolerance * (1 + 1e-6)) << "corner after line " << program[i].line;
    EXPECT_EQ(m.end_position, program.back().target);
    EXPECT_EQ(r.samples.back().velocity, AxisVector::Zero());
}

// The same for any program (zero-length blocks, exact stops, straight joins left out of the corners).
inline void expect_within_random(const RateRun& r, const std::vector<Block>& blocks, const PlannerParameters& p) {
    ASSERT_TRUE(r.ended);
    std::vector<AxisVector> points{AxisVector::Zero()};
    std::vector<const Block*> ending;
    for (const Block& b : blocks)
        if ((b.target - points.back()).norm() >= min_block_length) points.push_back(b.target), ending.push_back(&b);
    const Measured m = measure(r.samples, points, p.period);
    ASSERT_TRUE(m.finite);
    ASSERT_EQ(beyond_limits(r.samples, m, p), "");
    ASSERT_EQ(m.corner_errors.size(), points.size() - 2);
    for (std::size_t i = 0; i < m.corner_errors.size(); ++i) {
        const Block& b = *ending[i];
        const AxisVector in = points[i + 1] - points[i], out = points[i + 2] - points[i + 1];
        if (b.termination != Termination::blend || in.normalized().dot(out.normalized()) > 1.0 - 1e-12) continue;
        ASSERT_LE(m.corner_errors[i], b.tolerance * (1 + 1e-6) + 1e-9) << "corner after line " << b.line;
    }
    ASSERT_EQ(m.end_position, blocks.back().target);
    ASSERT_EQ(r.samples.back().velocity, AxisVector::Zero());
}

}  // namespace firtp::test
