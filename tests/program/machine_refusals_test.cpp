// Bad machine configurations are refused when the INI is loaded, with file:line and the key:
// filter times that cannot be built (a stage neither given nor derivable, untunable modes, a
// window too long for the planner) and limit keys that are misspelt. The per-value checks (zero,
// negative, NaN, not a number, unknown [FIRTP] keys) are in machine_test.cpp.
#include "machine_test_support.hpp"
#include <firtp/hal/component_logic.hpp>
#include <firtp/machine.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace {

using firtp::ConfigError;
using firtp::IniFile;
using firtp::test::load_error;

// A jerk limit of 1 gives T2 = a / j = 5000 s: before, this INI loaded and building its planner
// tried to allocate a 5-million-sample window (found by tests/fuzz/fuzz_ini as an out-of-memory).
// The fixed chain's window ([FIRTP]T1 given, the rest derived from the limits).
TEST(MachineRefusals, FilterWindowTooLongNamesTheLimitThatMakesIt) {
    EXPECT_EQ(load_error("[AXIS_X]\nMAX_VELOCITY = 300\nMAX_JERK = 1\n[FIRTP]\nT1 = 0.06\n"),
              "mill.ini:3: [AXIS_X]MAX_JERK: the filter delay T1 + ... + Tn = 5000.06 s is 5.00006e+06 servo periods "
              "(at most 20000): T2 = MAX_ACCELERATION / MAX_JERK = 5000 s");
    EXPECT_EQ(load_error("[AXIS_Y]\nMAX_VELOCITY = 30000\nMAX_ACCELERATION = 1\n[FIRTP]\nSTAGES = 1\nT1 = 30000\n"),
              "mill.ini:6: [FIRTP]T1: the filter delay T1 + ... + Tn = 30000 s is 3e+07 servo periods (at most 20000)");
    EXPECT_EQ(load_error("[FIRTP]\nSTAGES = 3\nT3 = 25\n"),
              "mill.ini:3: [FIRTP]T3: the filter delay T1 + ... + Tn = 25.11 s is 25110 servo periods (at most 20000)");
    EXPECT_EQ(load_error("[EMCMOT]\nSERVO_PERIOD = 1000\n[FIRTP]\nT1 = 0.06\n"),
              "mill.ini:2: [EMCMOT]SERVO_PERIOD: the filter delay T1 + ... + Tn = 0.11 s is 110000 servo periods "
              "(at most 20000): the servo period is too short");
    EXPECT_EQ(load_error("[FIRTP]\nMODES = 0.001\n"),
              "mill.ini:2: [FIRTP]MODES: the filter delay T1 + ... + Tn = 1000.05 s is 1.00005e+06 servo periods (at most "
              "20000)");
    // With modes, a bound longer than the window is refused before tuning, and a frequency that would
    // put more than a million of its periods in a stage (fuzz_ini: MODES = 888888888888884 Hz made
    // the tuner convert 4e13 to an int, undefined behaviour).
    EXPECT_EQ(load_error("[AXIS_X]\nMAX_JERK = 1\n[FIRTP]\nMODES = 10\n"),
              "mill.ini:2: [AXIS_X]MAX_JERK: the filter delay T1 + ... + Tn is at least 5000 s is 5e+06 servo periods "
              "(at most 20000): T2 = MAX_ACCELERATION / MAX_JERK = 5000 s");
    EXPECT_EQ(load_error("[FIRTP]\nMODES = 888888888888884/0.3\nROBUST = straddle 0.2\n"),
              "mill.ini:2: [FIRTP]MODES: 8.88889e+14 Hz: a filter stage of 0.06 s would span more than a million periods "
              "of this mode");
    // Long but within the window: accepted (20 s at 1 ms).
    EXPECT_EQ(load_error("[FIRTP]\nT1 = 10\nT2 = 9.9\n"), "no error");
    // Smoothing at the limits has no window: slow limits make slow moves, not a refusal.
    EXPECT_EQ(load_error("[AXIS_X]\nMAX_VELOCITY = 300\nMAX_JERK = 1\n"), "no error");
    EXPECT_EQ(load_error("[EMCMOT]\nSERVO_PERIOD = 1000\n"), "no error");
}

TEST(MachineRefusals, CoordinatesNameAxisLettersWithAccelerations) {
    EXPECT_EQ(load_error("[TRAJ]\nCOORDINATES = X Y Q\n"),
              "mill.ini:2: [TRAJ]COORDINATES: 'Q' is not an axis letter (X Y Z A B C U V W)");
    EXPECT_EQ(load_error("[TRAJ]\nCOORDINATES = X Y Z A\n"),
              "mill.ini:2: [TRAJ]COORDINATES: names A but [AXIS_A] gives no MAX_ACCELERATION");
}

TEST(MachineRefusals, StageNeitherGivenNorDerivableNamesStages) {
    const std::string no_jerk = "[AXIS_X]\nMAX_JERK = 0\n[AXIS_Y]\nMAX_JERK = 0\n[AXIS_Z]\nMAX_JERK = 0\n";
    EXPECT_EQ(load_error(no_jerk + "[FIRTP]\nSTAGES = 2\nT1 = 0.06\n"),
              "mill.ini:8: [FIRTP]STAGES: filter times: T2 is neither given nor derivable from the axis limits or a mode");
    EXPECT_EQ(load_error(no_jerk + "[FIRTP]\nT1 = 0.06\n"),
              "mill.ini:0: filter times: T2 is neither given nor derivable from the axis limits or a mode");
    EXPECT_EQ(load_error(no_jerk + "[FIRTP]\nSTAGES = 1\nT1 = 0.06\n"), "no error");
    EXPECT_EQ(load_error(no_jerk + "[FIRTP]\nT2 = 0.02\n"), "no error");
    EXPECT_EQ(load_error(no_jerk), "no error");  // smoothing at the limits: acceleration-limited only
}

// Smoothing at the limits needs each declared axis' acceleration limit.
TEST(MachineRefusals, DeclaredAxisWithoutAccelerationIsRefused) {
    EXPECT_EQ(load_error("[AXIS_C]\nMAX_VELOCITY = 3600\n"),
              "mill.ini:2: [AXIS_C]MAX_ACCELERATION is missing: moves are smoothed at each axis' acceleration limit "
              "(or give [FIRTP]T1 for the paper's fixed chain)");
    EXPECT_EQ(load_error("[AXIS_C]\nMAX_VELOCITY = 3600\n[FIRTP]\nT1 = 0.06\nT2 = 0.05\n"), "no error");
    EXPECT_EQ(load_error("[AXIS_C]\nMAX_VELOCITY = 3600\nMAX_ACCELERATION = 7200\n"), "no error");
}

TEST(MachineRefusals, UntunableModesNameModes) {
    const std::string error = load_error("[FIRTP]\nMODES = 5 6 7\nROBUST = double\n");
    EXPECT_EQ(error.rfind("mill.ini:2: [FIRTP]MODES: filter times: ", 0), 0u) << error;
}

// A misspelt limit would leave the built-in one (5000 mm/s^2) in force without a word.
TEST(MachineRefusals, MisspeltLimitKeysAreRefused) {
    const char* known = "unknown limit key (firtp reads MAX_VELOCITY, MAX_ACCELERATION, MAX_JERK; keys are case sensitive)";
    EXPECT_EQ(load_error("[AXIS_X]\nMAX_VELOCITY = 100\nMAX_ACCELLERATION = 500\n"),
              std::string("mill.ini:3: [AXIS_X]MAX_ACCELLERATION: ") + known);
    EXPECT_EQ(load_error("[AXIS_Z]\nmax_jerk = 1000\n"), std::string("mill.ini:2: [AXIS_Z]max_jerk: ") + known);
    EXPECT_EQ(load_error("[AXIS_B]\nMAXVELOCITY = 10\n"), std::string("mill.ini:2: [AXIS_B]MAXVELOCITY: ") + known);
    // LinuxCNC's own axis keys stay allowed.
    EXPECT_EQ(load_error("[AXIS_X]\nMIN_LIMIT = -10\nMAX_LIMIT = 10\nMAX_VELOCITY = 100\nFERROR = 1\n"), "no error");
}

// Whatever load_machine accepts, the component accepts (what firtp run and serve load).
TEST(MachineRefusals, AcceptedMachinesBuildTheComponent) {
    for (const char* text : {"[FIRTP]\nT1 = 10\nT2 = 9.9\n", "[EMCMOT]\nSERVO_PERIOD = 100000\n",
                             "[AXIS_X]\nMAX_JERK = 500\n", "[FIRTP]\nMODES = 6.8 11.4\n"}) {
        const firtp::MachineConfig m = firtp::load_machine(IniFile::parse(text, "m.ini"));
        firtp::ComponentSettings s;
        s.planner = m.planner_parameters();
        s.planner.queue_capacity = 8;
        EXPECT_NO_THROW(firtp::ComponentLogic core(s)) << text;
    }
}

// The component refuses a window too long for it (module parameters, settings made in code).
TEST(MachineRefusals, ComponentRefusesAWindowTooLong) {
    firtp::ComponentSettings s;
    s.planner.fixed_chain = true;
    s.planner.filters.stages = 2;
    s.planner.filters.T = {15.0, 10.0, 0.0, 0.0};
    s.planner.queue_capacity = 8;
    try {
        firtp::ComponentLogic core(s);
        FAIL() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "the filter delay T1 + ... + Tn is longer than 20000 servo periods (20 s at 1 ms)");
    }
}

}  // namespace
