// G4 P is a stop of the programmed length: the move before ends in an exact stop, the tool rests
// there P seconds (to the next servo sample) and the next move starts; the cycle time grows by P.
#include <firtp/gcode.hpp>
#include <firtp/machine.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

using firtp::AxisVector;
using firtp::MachineConfig;
using firtp::Trajectory;

Trajectory plan(const std::string& text, const MachineConfig& machine) {
    const firtp::Program program = firtp::parse_gcode(text, "dwell.ngc", machine);
    return firtp::plan_trajectory(machine.planner_parameters(), AxisVector::Zero(), program.blocks);
}

// Longest run of consecutive samples at rest (zero velocity) exactly at `point`, in seconds
// between its first and last sample.
double rest_at(const Trajectory& t, const AxisVector& point) {
    double longest = 0.0, first = -1.0;
    for (const firtp::AxisState& s : t.samples) {
        const bool resting = (s.position - point).norm() < 1e-9 && s.velocity.norm() == 0.0;
        if (resting && first < 0.0) first = s.time;
        if (!resting) first = -1.0;
        if (resting) longest = std::max(longest, s.time - first);
    }
    return longest;
}

void expect_dwell(const MachineConfig& machine, const char* mode) {
    // The same exact stop at X20, without and with the dwell.
    const Trajectory without = plan("G21 G90 G61\nG1 F3000 X20\nG64 P0.05\nG1 X20 Y20\nM2\n", machine);
    const Trajectory with = plan("G21 G90 G64 P0.05\nG1 F3000 X20\nG4 P0.5\nG1 X20 Y20\nM2\n", machine);
    const double period = machine.period;
    AxisVector corner = AxisVector::Zero();
    corner[0] = 20.0;
    EXPECT_NEAR(with.cycle_time, without.cycle_time + 0.5, period * 1.01) << mode;
    const double rest = rest_at(with, corner), rest_before = rest_at(without, corner);
    EXPECT_NEAR(rest - rest_before, 0.5, period * 1.01) << mode << ": at rest " << rest << " s, without dwell "
                                                        << rest_before << " s";
    EXPECT_GE(rest, 0.5 - 1e-9) << mode;
    EXPECT_LE(rest, 0.5 + 2 * period) << mode;
}

TEST(DwellTimeline, RestsTheProgrammedTimeAtTheStopAtTheLimits) { expect_dwell(firtp::default_machine(), "limits"); }

TEST(DwellTimeline, RestsTheProgrammedTimeAtTheStopWithThePapersChain) {
    MachineConfig machine = firtp::default_machine();
    machine.given_times = {0.040, 0.020};
    expect_dwell(machine, "paper");
}

TEST(DwellTimeline, ADwellBeforeTheFirstMoveDelaysIt) {
    const MachineConfig machine = firtp::default_machine();
    const Trajectory with = plan("G21 G90\nG4 P0.25\nG1 F3000 X20\nM2\n", machine);
    const Trajectory without = plan("G21 G90\nG1 F3000 X20\nM2\n", machine);
    EXPECT_NEAR(with.cycle_time, without.cycle_time + 0.25, machine.period * 1.01);
}

}  // namespace
