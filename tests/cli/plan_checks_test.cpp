// firtp plan / run exit with exit_check_failed (3) when the measurement finds a corner above its
// tolerance, an axis above a limit or an end off the program; each finding is named on stderr.
#include "plan_checks.hpp"

#include "cli_errors.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace firtp::cli {
namespace {

// The one corner's measured error.
void measured_error(PlanRun& run, double error) {
    run.corners.clear_errors();
    run.corners.add_error(error);
    run.corners.pair_errors();
}

PlanRun clean_run() {
    PlanRun run;
    run.parameters.limits.axes = 2;
    for (int a = 0; a < 2; ++a) run.parameters.limits.axis[a] = {10.0, 100.0, 1000.0};
    AxisVector end = AxisVector::Zero();
    end[0] = 1.0;
    run.points = {AxisVector::Zero(), end, AxisVector::Zero()};
    run.measured.end_position = AxisVector::Zero();
    run.measured.max_velocity[0] = 10.0;  // at the limits, not above
    run.measured.max_acceleration[0] = 100.0;
    run.measured.max_jerk[0] = 1000.0;
    CornerReport corner;
    corner.line = 7;
    corner.epsilon = 0.01;
    run.corners.push_back(corner);
    measured_error(run, 0.01);
    return run;
}

TEST(PlanChecks, AtTheLimitsAndTheToleranceNothingIsReported) {
    std::ostringstream err;
    EXPECT_EQ(report_violations(err, clean_run()), 0);
    EXPECT_EQ(err.str(), "");
}

TEST(PlanChecks, EachFindingIsNamedAndTheExitStatusSaysSo) {
    PlanRun run = clean_run();
    measured_error(run, 0.0125);
    run.measured.max_velocity[1] = 10.5;
    run.measured.max_jerk[0] = 1200.0;
    run.measured.end_position[0] = 0.001;
    std::ostringstream err;
    EXPECT_EQ(report_violations(err, run), exit_check_failed);
    EXPECT_EQ(err.str(),
              "firtp: measured: corner at line 7: error 0.0125 mm above its tolerance 0.01 mm\n"
              "firtp: measured: axis Y velocity 10.5 mm/s above its limit 10\n"
              "firtp: measured: axis X jerk 1200 mm/s^3 above its limit 1000\n"
              "firtp: measured: the tool rests 0.001 mm from the program's end\n");
}

TEST(PlanChecks, WithContourToleranceThePathIsHeldToItNotTheCornerPoints) {
    PlanRun run = clean_run();
    run.parameters.tolerance_meaning = ToleranceMeaning::contour;
    measured_error(run, 0.014);  // the corner point may be farther than the tolerance
    run.measured.max_contour_error = 0.01;
    std::ostringstream err;
    EXPECT_EQ(report_violations(err, run), 0);
    run.measured.max_contour_error = 0.011;
    EXPECT_EQ(report_violations(err, run), exit_check_failed);
    EXPECT_EQ(err.str(), "firtp: measured: contour error 0.011 mm above the tolerance 0.01 mm\n");
}

}  // namespace
}  // namespace firtp::cli
