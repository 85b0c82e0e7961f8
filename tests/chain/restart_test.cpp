// firtp.so unloaded and loaded again while the axes move (a component restart): the new one takes
// over from firtp.axis.N.pos-fb and vel-fb, so its first command is where the axes are at the
// speed they have, and it brakes them through the chain within the axis limits, reporting it.
// Loaded through hal-shim, block pins only; a drive model closes the loop.
#include <firtp/hal_shim/runtime.hpp>
#include <firtp/in_process_component.hpp>

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

namespace shim = firtp::hal_shim;

constexpr int axes = 3;
constexpr double servo_period = 0.001, v_max = 250.0, a_max = 3000.0, j_max = 1e5;
const std::vector<std::string> arguments = {
    "axes=3", "stages=2", "t1=0.1", "t2=0.03", "block_key=0", "state_key=0",
    "max_velocity=250,250,250", "max_acceleration=3000,3000,3000", "max_jerk=1e5,1e5,1e5"};

void ok(const shim::Status& status) { ASSERT_TRUE(status.ok()) << status.message; }

double get(const std::string& pin) {
    shim::Value value;
    EXPECT_TRUE(shim::get_value(pin, value).ok()) << pin;
    return value.as_double();
}

void set(const std::string& pin, double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    ASSERT_TRUE(shim::set_value(pin, std::string(text, end)).ok()) << pin;
}

std::string axis_pin(int a, const char* name) { return "firtp.axis." + std::to_string(a) + "." + name; }

void load_component() {
    ok(shim::load_module(firtp::default_module_path().string(), arguments));
    ok(shim::add_funct("firtp.update", "servo-thread"));
}

// Axes that follow the command exactly, and coast at their velocity while nothing commands them.
struct Drive {
    double p[axes] = {}, v[axes] = {};
    void follow() {
        for (int a = 0; a < axes; ++a) {
            p[a] = get(axis_pin(a, "pos-cmd"));
            v[a] = get(axis_pin(a, "vel-cmd"));
        }
    }
    void coast() {
        for (int a = 0; a < axes; ++a) p[a] += v[a] * servo_period;
    }
    void feed_back() {
        for (int a = 0; a < axes; ++a) {
            set(axis_pin(a, "pos-fb"), p[a]);
            set(axis_pin(a, "vel-fb"), v[a]);
        }
    }
};

}  // namespace

TEST(ComponentRestart, TheNewComponentBrakesFromTheFeedbackWithinTheLimits) {
    ok(shim::new_thread("servo-thread", 1000000));
    load_component();
    ok(shim::set_value("firtp.enable", "1"));
    Drive drive;
    // One long move: X 300, Y -100 at 200 mm/s, through the block pins.
    set("firtp.block.target.0", 300.0);
    set("firtp.block.target.1", -100.0);
    set("firtp.block.feed", 200.0);
    ok(shim::set_value("firtp.block.exact-stop", "1"));
    ok(shim::set_value("firtp.block.strobe", "1"));
    for (int k = 0; k < 600; ++k) {
        drive.feed_back();
        ok(shim::step(1));
        drive.follow();
    }
    const double speed = std::hypot(drive.v[0], drive.v[1]);
    ASSERT_GT(speed, 199.0);  // at full feed

    ok(shim::unload_module("firtp"));  // the component goes away ...
    for (int k = 0; k < 5; ++k) drive.coast();  // ... while the axes coast on
    load_component();                           // ... and comes back with the same parameters
    ok(shim::set_value("firtp.enable", "1"));

    const double p0[axes] = {drive.p[0], drive.p[1], drive.p[2]}, v0[axes] = {drive.v[0], drive.v[1], drive.v[2]};
    double jump = 0.0, velocity_step = 0.0, worst_a = 0.0, worst_j = 0.0, previous_a[axes] = {};
    int ticks = 0;
    for (; ticks < 1000; ++ticks) {
        drive.feed_back();
        ok(shim::step(1));
        const double before[axes] = {drive.v[0], drive.v[1], drive.v[2]};
        drive.follow();
        for (int a = 0; a < axes; ++a) {
            const double acc = get(axis_pin(a, "acc-cmd"));
            if (ticks == 0) {
                jump = std::max(jump, std::abs(drive.p[a] - p0[a]));
                velocity_step = std::max(velocity_step, std::abs(drive.v[a] - v0[a]));
            } else {
                worst_a = std::max(worst_a, std::abs(drive.v[a] - before[a]) / servo_period);  // finite differences
                worst_j = std::max(worst_j, std::abs(acc - previous_a[a]) / servo_period);
            }
            ASSERT_LE(std::abs(drive.v[a]), v_max * (1 + 1e-9));
            ASSERT_LE(std::abs(acc), a_max * (1 + 1e-9));
            previous_a[a] = acc;
        }
        if (ticks == 0) {
            EXPECT_EQ(get("firtp.state"), 3.0);        // stopping
            EXPECT_EQ(get("firtp.error-code"), 8.0);   // ERROR_STOPPED_FROM_FEEDBACK
        }
        if (drive.v[0] == 0.0 && drive.v[1] == 0.0) break;
    }
    EXPECT_LT(jump, 1e-9);
    EXPECT_LT(velocity_step, 1e-6);
    EXPECT_LE(worst_a, a_max);
    EXPECT_LE(worst_j, j_max * (1 + 1e-6));
    const double td = 0.13;  // T1 + T2
    EXPECT_NEAR(ticks * servo_period, td, 0.002);
    for (int a = 0; a < axes; ++a) EXPECT_NEAR(drive.p[a], p0[a] + v0[a] * td / 2, 1e-9);  // rest: p + v Td / 2
    EXPECT_EQ(get("firtp.state"), 4.0);  // error: the interrupted motion does not go on
    std::printf("restarted at %.1f mm/s: first command %.2g mm / %.2g mm/s from the feedback; braked in %d ms over "
                "%.2f mm; worst |a| %.0f of %.0f, |j| %.0f of %.0f mm/s^3\n",
                speed, jump, velocity_step, ticks, speed * td / 2, worst_a, a_max, worst_j, j_max);
    shim::unload_module("firtp");
    shim::delete_thread("servo-thread");
}
