// A path planned as drawn and with every tolerance a quarter looser (firtp_cliffs' tolerance
// raise), each within its limits and tolerances on the samples (case_ratios).
#pragma once

#include "case_ratios.hpp"

#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <vector>

namespace firtp::test {

// The two trajectories: [0] as drawn, [1] a quarter looser.
inline std::array<Trajectory, 2> as_drawn_and_looser(const PlannerParameters& p, const std::vector<Block>& blocks) {
    std::array<Trajectory, 2> planned;
    for (const std::size_t looser : {0u, 1u}) {
        std::vector<Block> path = blocks;
        if (looser)
            for (Block& b : path) b.tolerance *= 1.25;
        SCOPED_TRACE(looser ? "tolerances a quarter looser" : "tolerances as drawn");
        planned[looser] = plan_trajectory(p, AxisVector::Zero(), path);
        const CaseRatios r = case_ratios(p, path, planned[looser]);
        EXPECT_TRUE(r.within()) << "corner " << r.corner << " v " << r.velocity << " a " << r.acceleration << " j " << r.jerk;
        std::printf("%s: cycle %.5f s\n", looser ? "looser" : "as drawn", planned[looser].cycle_time);
    }
    return planned;
}

}  // namespace firtp::test
