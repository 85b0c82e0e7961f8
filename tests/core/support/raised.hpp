// A path planned as drawn and with a limit raised by a quarter as firtp_cliffs raises it (every
// tolerance looser, or every axis' velocity or acceleration higher), each within its limits and
// tolerances on the samples (case_ratios), and whether the raised one is slower (expect_no_cliff).
#pragma once

#include "case_ratios.hpp"

#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <vector>

namespace firtp::test {

enum class Raised { tolerance, velocity, acceleration };

// The two trajectories: [0] as drawn, [1] raised.
inline std::array<Trajectory, 2> as_drawn_and_raised(const PlannerParameters& drawn, const std::vector<Block>& blocks,
                                                     Raised what = Raised::tolerance, const AxisVector& start = AxisVector::Zero()) {
    std::array<Trajectory, 2> planned;
    for (const std::size_t raised : {0u, 1u}) {
        PlannerParameters p = drawn;
        std::vector<Block> path = blocks;
        if (raised && what == Raised::tolerance)
            for (Block& b : path) b.tolerance *= 1.25;
        for (int a = 0; raised && a < p.limits.axes; ++a) {
            if (what == Raised::velocity) p.limits.axis[a].max_velocity *= 1.25;
            if (what == Raised::acceleration) p.limits.axis[a].max_acceleration *= 1.25;
        }
        SCOPED_TRACE(raised ? "raised by a quarter" : "as drawn");
        planned[raised] = plan_trajectory(p, start, path);
        const CaseRatios r = case_ratios(p, path, planned[raised], start);
        EXPECT_TRUE(r.within()) << "corner " << r.corner << " v " << r.velocity << " a " << r.acceleration << " j " << r.jerk;
        std::printf("%s: cycle %.5f s\n", raised ? "raised" : "as drawn", planned[raised].cycle_time);
    }
    return planned;
}

// No cliff: the raised plan no slower than the one as drawn, but for the tick grid (a period).
inline void expect_no_cliff(const std::array<Trajectory, 2>& t, const PlannerParameters& drawn) {
    EXPECT_LE(t[1].cycle_time, t[0].cycle_time + drawn.period) << "slower with the limit raised by a quarter";
}

}  // namespace firtp::test
