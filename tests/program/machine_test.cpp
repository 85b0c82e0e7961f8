#include "machine_test_support.hpp"
#include <firtp/machine.hpp>

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace {

using firtp::ConfigError;
using firtp::IniFile;
using firtp::test::load_error;
using firtp::MachineConfig;

constexpr const char* sample_ini = R"(# A LinuxCNC INI with firtp keys
[EMC]
MACHINE = test mill

[EMCMOT]
EMCMOT = motmod
SERVO_PERIOD = 500000

[TRAJ]
COORDINATES = X Y Z A
LINEAR_UNITS = mm
MAX_LINEAR_VELOCITY = 250

[AXIS_X]
MAX_VELOCITY = 200
MAX_ACCELERATION = 2000
MIN_LIMIT = -10

[AXIS_Y]
MAX_VELOCITY = 150

[AXIS_A]
MAX_VELOCITY = 90
MAX_ACCELERATION = 900
MAX_JERK = 0

[FIRTP]
STAGES = 3
T3 = 0.004
MODES = 40  55.5
TOLERANCE = 0.02
TOLERANCE_MEANING = contour
ARC_CHORD_TOLERANCE = 0.005
)";

TEST(Machine, DefaultMachine) {
    const MachineConfig m = firtp::default_machine();
    EXPECT_EQ(m.period, 0.001);
    EXPECT_EQ(m.limits.axes, 3);
    EXPECT_EQ(m.limits.max_linear_velocity, 0.0);
    for (std::size_t a = 0; a < 3; ++a) {
        EXPECT_EQ(m.limits.axis[a].max_velocity, 300.0);
        EXPECT_EQ(m.limits.axis[a].max_acceleration, 5000.0);
        EXPECT_EQ(m.limits.axis[a].max_jerk, 100000.0);
    }
    for (std::size_t a = 3; a < 9; ++a) EXPECT_EQ(m.limits.axis[a].max_velocity, 0.0);
    EXPECT_EQ(m.stages, 2);
    EXPECT_TRUE(m.given_times.empty());
    EXPECT_TRUE(m.tuning.modes.empty());
    EXPECT_EQ(m.default_tolerance, 0.05);
    EXPECT_EQ(m.tolerance_meaning, firtp::ToleranceMeaning::corner_point);
    EXPECT_EQ(m.arc_chord_tolerance, 0.001);
    EXPECT_EQ(firtp::load_machine(IniFile::parse("[FIRTP]\nTOLERANCE = 0.1\n", "m.ini")).arc_chord_tolerance, 0.001);
}

// One jerk setting for firtp and firtp_tp: [TRAJ]MAX_LINEAR_JERK (LinuxCNC master's key) bounds every
// linear axis, alone or below its own [AXIS_L]MAX_JERK; rotary axes keep theirs.
TEST(Machine, MaxLinearJerkBoundsTheLinearAxes) {
    const MachineConfig m = firtp::load_machine(IniFile::parse(
        "[TRAJ]\nMAX_LINEAR_JERK = 20000\n[AXIS_X]\nMAX_JERK = 50000\n[AXIS_Y]\nMAX_JERK = 10000\n[AXIS_Z]\n"
        "MAX_VELOCITY = 100\n[AXIS_A]\nMAX_VELOCITY = 3600\nMAX_ACCELERATION = 36000\nMAX_JERK = 1000000\n",
        "m.ini"));
    EXPECT_EQ(m.limits.axis[0].max_jerk, 20000.0);    // its own 50000 is above
    EXPECT_EQ(m.limits.axis[1].max_jerk, 10000.0);    // its own is below
    EXPECT_EQ(m.limits.axis[2].max_jerk, 20000.0);    // none of its own
    EXPECT_EQ(m.limits.axis[3].max_jerk, 1000000.0);  // rotary: untouched
    const MachineConfig zero = firtp::load_machine(IniFile::parse("[TRAJ]\nMAX_LINEAR_JERK = 0\n[AXIS_X]\nMAX_JERK = 50000\n", "m.ini"));
    EXPECT_EQ(zero.limits.axis[0].max_jerk, 50000.0);  // 0: not set
}

// [TRAJ]COORDINATES names the axes, as LinuxCNC reads it: a lathe's "X Z" has no Y (a move of it is
// refused when planned), whatever the built-in machine has; a letter twice is a gantry, one axis.
TEST(Machine, CoordinatesNameTheAxes) {
    const MachineConfig lathe = firtp::load_machine(IniFile::parse(
        "[TRAJ]\nCOORDINATES = X Z\n[AXIS_X]\nMAX_ACCELERATION = 1000\n[AXIS_Z]\nMAX_ACCELERATION = 2000\n", "lathe.ini"));
    EXPECT_EQ(lathe.limits.axes, 3);
    EXPECT_EQ(lathe.limits.axis[0].max_acceleration, 1000.0);
    EXPECT_EQ(lathe.limits.axis[1].max_acceleration, 0.0);
    EXPECT_EQ(lathe.limits.axis[1].max_velocity, 0.0);
    EXPECT_EQ(lathe.limits.axis[2].max_acceleration, 2000.0);
    const MachineConfig gantry = firtp::load_machine(IniFile::parse("[TRAJ]\nCOORDINATES = XYYZ\n", "gantry.ini"));
    EXPECT_EQ(gantry.limits.axes, 3);
    for (int a = 0; a < 3; ++a) EXPECT_GT(gantry.limits.axis[a].max_acceleration, 0.0) << a;
    const MachineConfig mill = firtp::load_machine(IniFile::parse("[AXIS_X]\nMAX_ACCELERATION = 1000\n", "mill.ini"));
    EXPECT_GT(mill.limits.axis[1].max_acceleration, 0.0);  // without COORDINATES: the built-in X Y Z
}

// Without T1 or MODES the machine smooths at its limits; filter_times() (the fixed chain's, when
// only some times are given) still derives the rest from the limits.
TEST(Machine, DefaultMachineSmoothsAtItsLimits) {
    const firtp::MachineConfig m = firtp::default_machine();
    EXPECT_FALSE(m.fixed_chain());
    const firtp::FilterTimes f = m.filter_times();
    EXPECT_EQ(f.stages, 2);
    EXPECT_DOUBLE_EQ(f.T[0], 0.06);  // 300 / 5000
    EXPECT_DOUBLE_EQ(f.T[1], 0.05);  // 5000 / 100000
    const firtp::PlannerParameters p = m.planner_parameters();
    EXPECT_FALSE(p.fixed_chain);
    EXPECT_EQ(p.limits.axis[0].max_acceleration, 5000.0);
    EXPECT_EQ(p.period, 0.001);
    EXPECT_EQ(p.tolerance_meaning, firtp::ToleranceMeaning::corner_point);
}

TEST(Machine, LoadsSampleIniOverDefaults) {
    const MachineConfig m = firtp::load_machine(IniFile::parse(sample_ini, "mill.ini"));
    EXPECT_DOUBLE_EQ(m.period, 0.0005);
    EXPECT_EQ(m.limits.max_linear_velocity, 250.0);
    EXPECT_EQ(m.limits.axes, 4);  // A is index 3
    EXPECT_EQ(m.limits.axis[0].max_velocity, 200.0);
    EXPECT_EQ(m.limits.axis[0].max_acceleration, 2000.0);
    EXPECT_EQ(m.limits.axis[0].max_jerk, 100000.0);  // default kept
    EXPECT_EQ(m.limits.axis[1].max_velocity, 150.0);
    EXPECT_EQ(m.limits.axis[1].max_acceleration, 5000.0);
    EXPECT_EQ(m.limits.axis[2].max_velocity, 300.0);
    EXPECT_EQ(m.limits.axis[3].max_velocity, 90.0);
    EXPECT_EQ(m.limits.axis[3].max_acceleration, 900.0);
    EXPECT_EQ(m.limits.axis[3].max_jerk, 0.0);
    EXPECT_EQ(m.stages, 3);
    ASSERT_EQ(m.given_times.size(), 3u);
    EXPECT_EQ(m.given_times[0], 0.0);
    EXPECT_EQ(m.given_times[1], 0.0);
    EXPECT_EQ(m.given_times[2], 0.004);
    ASSERT_EQ(m.tuning.modes.size(), 2u);
    EXPECT_EQ(m.tuning.modes[0].frequency_hz, 40.0);
    EXPECT_EQ(m.tuning.modes[1].frequency_hz, 55.5);
    EXPECT_EQ(m.tuning.modes[0].damping, firtp::default_mode_damping);
    EXPECT_EQ(m.tuning.modes[0].axis, -1);
    EXPECT_EQ(m.default_tolerance, 0.02);
    EXPECT_EQ(m.tolerance_meaning, firtp::ToleranceMeaning::contour);
    EXPECT_EQ(m.arc_chord_tolerance, 0.005);
}

TEST(Machine, HighestAxisSetsAxisCount) {
    EXPECT_EQ(firtp::load_machine(IniFile::parse("[AXIS_W]\nMAX_VELOCITY = 5\nMAX_ACCELERATION = 50\n", "m.ini")).limits.axes, 9);
    EXPECT_EQ(firtp::load_machine(IniFile::parse("[AXIS_X]\nMAX_VELOCITY = 5\n", "m.ini")).limits.axes, 3);
    EXPECT_EQ(firtp::load_machine(IniFile::parse("[EMC]\nX = 1\n", "m.ini")).limits.axes, 3);
}

TEST(Machine, TimesGivenInIniReachFilterTimes) {
    const MachineConfig m =
        firtp::load_machine(IniFile::parse("[FIRTP]\nT1 = 0.03\nT2 = 0.01\nSTAGES = 2\n", "m.ini"));
    const firtp::FilterTimes f = m.filter_times();
    EXPECT_EQ(f.T[0], 0.03);
    EXPECT_EQ(f.T[1], 0.01);
}

TEST(Machine, ValueErrorsNameFileLineAndKey) {
    EXPECT_EQ(load_error("[EMCMOT]\nSERVO_PERIOD = 1ms\n"), "mill.ini:2: [EMCMOT]SERVO_PERIOD: '1ms' is not a number");
    EXPECT_EQ(load_error("[EMCMOT]\nSERVO_PERIOD = 0\n"), "mill.ini:2: [EMCMOT]SERVO_PERIOD: '0' must be positive");
    EXPECT_EQ(load_error("[EMCMOT]\nSERVO_PERIOD = 1000.5\n"),
              "mill.ini:2: [EMCMOT]SERVO_PERIOD: must be a whole number of nanoseconds");
    EXPECT_EQ(load_error("[TRAJ]\nMAX_LINEAR_VELOCITY = -1\n"),
              "mill.ini:2: [TRAJ]MAX_LINEAR_VELOCITY: '-1' must be positive");
    EXPECT_EQ(load_error("[AXIS_Y]\n\nMAX_VELOCITY = nan\n"), "mill.ini:3: [AXIS_Y]MAX_VELOCITY: 'nan' is not a number");
    EXPECT_EQ(load_error("[AXIS_Z]\nMAX_ACCELERATION = 0\n"),
              "mill.ini:2: [AXIS_Z]MAX_ACCELERATION: '0' must be positive");
    EXPECT_EQ(load_error("[AXIS_B]\nMAX_JERK = -5\n"), "mill.ini:2: [AXIS_B]MAX_JERK: '-5' must be zero or positive");
    EXPECT_EQ(load_error("[AXIS_X]\nMAX_VELOCITY = inf\n"), "mill.ini:2: [AXIS_X]MAX_VELOCITY: 'inf' is not a number");
}

TEST(Machine, FirtpSectionErrors) {
    EXPECT_EQ(load_error("[FIRTP]\nSTAGES = 2\nT5 = 0.1\n"),
              "mill.ini:3: [FIRTP]T5: unknown key (known: STAGES, T1..T4, MODES, TOLERANCE, TOLERANCE_MEANING, "
              "ARC_CHORD_TOLERANCE, RATE_RESERVE, ROBUST, MAX_PROGRAM_BLOCKS)");
    EXPECT_EQ(load_error("[FIRTP]\nRATE_RESERVE = 1\n"),
              "mill.ini:2: [FIRTP]RATE_RESERVE: must be below 1 (a share of the acceleration and jerk limits)");
    EXPECT_EQ(load_error("[FIRTP]\nRATE_RESERVE = 0\n"), "mill.ini:2: [FIRTP]RATE_RESERVE: '0' must be positive");
    EXPECT_EQ(load_error("[DISPLAY]\nMAX_FEED_OVERRIDE = 0.5\n"),
              "mill.ini:2: [DISPLAY]MAX_FEED_OVERRIDE: must be at least 1 (100 %)");
    EXPECT_EQ(load_error("[FIRTP]\nSTAGES = 5\n"), "mill.ini:2: [FIRTP]STAGES: must be a whole number from 1 to 4");
    EXPECT_EQ(load_error("[FIRTP]\nSTAGES = 1.5\n"), "mill.ini:2: [FIRTP]STAGES: must be a whole number from 1 to 4");
    EXPECT_EQ(load_error("[FIRTP]\nSTAGES = 0\n"), "mill.ini:2: [FIRTP]STAGES: must be a whole number from 1 to 4");
    EXPECT_EQ(load_error("[FIRTP]\nT2 = 0\n"), "mill.ini:2: [FIRTP]T2: '0' must be positive");
    EXPECT_EQ(load_error("[FIRTP]\nT1 = x\n"), "mill.ini:2: [FIRTP]T1: 'x' is not a number");
    EXPECT_EQ(load_error("[FIRTP]\nMODES = 40 abc\n"), "mill.ini:2: [FIRTP]MODES: 'abc' is not a number");
    EXPECT_EQ(load_error("[FIRTP]\nMODES = 40 -3\n"), "mill.ini:2: [FIRTP]MODES: '-3' must be a positive frequency in Hz");
    EXPECT_EQ(load_error("[FIRTP]\nMODES = inf\n"), "mill.ini:2: [FIRTP]MODES: 'inf' is not a number");
    EXPECT_EQ(load_error("[FIRTP]\nTOLERANCE = -0.1\n"), "mill.ini:2: [FIRTP]TOLERANCE: '-0.1' must be positive");
    EXPECT_EQ(load_error("[FIRTP]\nTOLERANCE_MEANING = max\n"),
              "mill.ini:2: [FIRTP]TOLERANCE_MEANING: 'max' must be corner or contour");
    EXPECT_EQ(load_error("[FIRTP]\nARC_CHORD_TOLERANCE = 0\n"),
              "mill.ini:2: [FIRTP]ARC_CHORD_TOLERANCE: '0' must be positive");
    EXPECT_EQ(load_error("[FIRTP]\nARC_CHORD_TOLERANCE = -0.01\n"),
              "mill.ini:2: [FIRTP]ARC_CHORD_TOLERANCE: '-0.01' must be positive");
    EXPECT_EQ(load_error("[FIRTP]\nARC_CHORD_TOLERANCE = 1um\n"),
              "mill.ini:2: [FIRTP]ARC_CHORD_TOLERANCE: '1um' is not a number");
}

TEST(Machine, IgnoresUnknownKeysOutsideFirtp) {
    EXPECT_EQ(load_error("[AXIS_X]\nFERROR = whatever\n[DISPLAY]\nDISPLAY = axis\n"), "no error");
}

TEST(Machine, FilterTimesErrorBecomesConfigError) {
    MachineConfig m = firtp::default_machine();
    m.limits.axis = {};  // nothing to derive T1 from, nor to smooth at
    EXPECT_THROW(m.filter_times(), ConfigError);
    EXPECT_THROW(m.planner_parameters(), ConfigError);
    m.given_times = {0.05};  // the fixed chain: T2 still underivable
    EXPECT_THROW(m.planner_parameters(), ConfigError);
}

TEST(Machine, OverridesSetTimesToleranceAndPeriod) {
    MachineConfig m = firtp::default_machine();
    m.stages = 1;
    firtp::MachineOverrides all;
    all.t1 = 0.08;
    all.t2 = 0.02;
    all.tolerance = 0.2;
    all.period = 0.00025;
    firtp::apply_overrides(m, all);
    ASSERT_EQ(m.given_times.size(), 2u);
    EXPECT_EQ(m.given_times[0], 0.08);
    EXPECT_EQ(m.given_times[1], 0.02);
    EXPECT_EQ(m.stages, 2);
    EXPECT_EQ(m.default_tolerance, 0.2);
    EXPECT_EQ(m.period, 0.00025);

    MachineConfig only_t2 = firtp::default_machine();
    firtp::MachineOverrides t2;
    t2.t2 = 0.01;
    firtp::apply_overrides(only_t2, t2);
    ASSERT_EQ(only_t2.given_times.size(), 2u);
    EXPECT_EQ(only_t2.given_times[0], 0.0);  // still derived from the limits
    EXPECT_DOUBLE_EQ(only_t2.filter_times().T[0], 0.06);
    EXPECT_EQ(only_t2.filter_times().T[1], 0.01);

    MachineConfig four = firtp::default_machine();
    four.stages = 4;
    four.given_times = {0.1, 0.05, 0.02, 0.01};
    firtp::MachineOverrides t1;
    t1.t1 = 0.2;
    firtp::apply_overrides(four, t1);
    EXPECT_EQ(four.stages, 4);
    EXPECT_EQ(four.given_times.size(), 4u);
    EXPECT_EQ(four.given_times[0], 0.2);
}

TEST(Machine, OverrideErrorsNameTheFlag) {
    const auto error = [](auto field, double value) {
        firtp::MachineOverrides o;
        o.*field = value;
        MachineConfig m = firtp::default_machine();
        try {
            firtp::apply_overrides(m, o);
        } catch (const ConfigError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error(&firtp::MachineOverrides::t1, 0.0), "--t1: must be a positive number of seconds");
    EXPECT_EQ(error(&firtp::MachineOverrides::t2, -1.0), "--t2: must be a positive number of seconds");
    EXPECT_EQ(error(&firtp::MachineOverrides::tolerance, std::numeric_limits<double>::quiet_NaN()),
              "--tolerance: must be a positive length in mm");
    EXPECT_EQ(error(&firtp::MachineOverrides::period, std::numeric_limits<double>::infinity()),
              "--period: must be a positive number of seconds");
    EXPECT_EQ(error(&firtp::MachineOverrides::tolerance, 1e-6), "no error");
}

}  // namespace

TEST(Machine, FeedOverrideAndRateReserveReachThePlanner) {
    const MachineConfig m =
        firtp::load_machine(IniFile::parse("[DISPLAY]\nMAX_FEED_OVERRIDE = 1.5\n[FIRTP]\nRATE_RESERVE = 0.3\n", "m.ini"));
    const firtp::PlannerParameters p = m.planner_parameters();
    EXPECT_EQ(p.max_rate, 1.5);
    EXPECT_EQ(p.rate_reserve, 0.3);
    const firtp::PlannerParameters d = firtp::default_machine().planner_parameters();
    EXPECT_EQ(d.max_rate, 1.0);  // as LinuxCNC: no MAX_FEED_OVERRIDE, no override above 100 %
    EXPECT_EQ(d.rate_reserve, 0.2);
}

namespace modes_ini {

// [FIRTP]MODES with damping and axes, ROBUST: the paper's diamond modes tuned into the chain.
TEST(Machine, ModesWithDampingAxesAndRobust) {
    const MachineConfig m = firtp::load_machine(IniFile::parse(
        "[AXIS_X]\nMAX_VELOCITY = 300\nMAX_ACCELERATION = 5000\n[AXIS_Y]\nMAX_VELOCITY = 300\n"
        "MAX_ACCELERATION = 5000\n[FIRTP]\nMODES = X:11.4/0.03, y:6.8/0.02 25\n",
        "m.ini"));
    ASSERT_EQ(m.tuning.modes.size(), 3u);
    EXPECT_EQ(m.tuning.modes[0].axis, 0);
    EXPECT_EQ(m.tuning.modes[0].frequency_hz, 11.4);
    EXPECT_EQ(m.tuning.modes[0].damping, 0.03);
    EXPECT_EQ(m.tuning.modes[1].axis, 1);
    EXPECT_EQ(m.tuning.modes[2].axis, -1);
    EXPECT_EQ(m.tuning.modes[2].damping, firtp::default_mode_damping);
    EXPECT_EQ(m.tuning.robust, firtp::RobustTuning::none);
    const firtp::TunedFilters tuned = m.tuned_filters();
    ASSERT_EQ(tuned.filters.stages, 3);  // three modes, three stages
    EXPECT_EQ(m.filter_times().stages, 3);

    MachineConfig robust = firtp::load_machine(IniFile::parse(
        "[AXIS_X]\nMAX_JERK = 100000\n[FIRTP]\nMODES = 6.8/0.02 11.4/0.03\nROBUST = straddle 0.15\n", "m.ini"));
    EXPECT_EQ(robust.tuning.robust, firtp::RobustTuning::straddle);
    EXPECT_EQ(robust.tuning.spread, 0.15);
    EXPECT_EQ(robust.filter_times().stages, 4);
    firtp::parse_robust("double", robust.tuning);
    EXPECT_EQ(robust.tuning.robust, firtp::RobustTuning::double_stage);
    EXPECT_EQ(robust.tuning.spread, 0.0);
    firtp::parse_robust("Straddle:0.2", robust.tuning);
    EXPECT_EQ(robust.tuning.spread, 0.2);
}

TEST(Machine, ModeErrorsNameFileLineAndKey) {
    EXPECT_EQ(load_error("[FIRTP]\nMODES = 6.8/2\n"), "mill.ini:2: [FIRTP]MODES: '6.8/2': the damping must lie in [0, 1)");
    EXPECT_EQ(load_error("[FIRTP]\nMODES = 6.8/x\n"), "mill.ini:2: [FIRTP]MODES: '6.8/x': the damping is not a number");
    EXPECT_EQ(load_error("[FIRTP]\nMODES = A:6.8\n"), "mill.ini:2: [FIRTP]MODES: 'A:6.8': 'A' is not an axis of this machine");
    EXPECT_EQ(load_error("[FIRTP]\nROBUST = triple\n"),
              "mill.ini:2: [FIRTP]ROBUST: 'triple' must be none, double, straddle or straddle SPREAD (0 < SPREAD < 0.5)");
    EXPECT_EQ(load_error("[FIRTP]\nROBUST = straddle 0.7\n"),
              "mill.ini:2: [FIRTP]ROBUST: 'straddle 0.7' must be none, double, straddle or straddle SPREAD (0 < SPREAD < 0.5)");
    // Modes that cannot be tuned are refused at load (machine_refusals_test.cpp).
    EXPECT_THROW(firtp::load_machine(IniFile::parse("[FIRTP]\nMODES = 5 6 7\nROBUST = double\n", "m.ini")), ConfigError);
}

}  // namespace modes_ini
