// firtp.so refuses bad module parameters at load (loadrt firtp ...), printing a message that
// names the parameter: not numbers, zero or negative where positive is needed, NaN, limits lists,
// filter times the planner cannot be built for. Loaded through hal-shim as firtp-hal does.
#include <firtp/hal_shim/runtime.hpp>
#include <firtp/in_process_component.hpp>
#define RTAPI  // for rtapi_set_msg_handler, as hal-shim's own tests
#include <rtapi.h>

#include <gtest/gtest.h>

#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

namespace {

namespace shim = firtp::hal_shim;

std::string printed;  // what the component printed while loading

void capture(msg_level_t, const char* format, va_list ap) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, ap);
    printed += text;
}

// The message of a refused load, or "loaded".
std::string load(const std::vector<std::string>& args) {
    printed.clear();
    rtapi_set_msg_handler(capture);
    const shim::Status status = shim::load_module(firtp::default_module_path().string(), args);
    rtapi_set_msg_handler(nullptr);
    if (status.ok()) {
        shim::unload_module("firtp");
        return "loaded";
    }
    return printed;
}

}  // namespace

TEST(ModuleParams, BadValuesAreRefusedNamingTheParameter) {
    const std::vector<std::string> base = {"t1=0.06", "t2=0.05"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = base;
        args.insert(args.end(), extra.begin(), extra.end());
        return load(args);
    };
    EXPECT_EQ(with({}), "loaded");
    EXPECT_EQ(with({"t1=abc"}), "firtp: t1=abc: not a finite number\n");
    EXPECT_EQ(with({"t1=0.1x"}), "firtp: t1=0.1x: not a finite number\n");
    EXPECT_EQ(with({"t2=nan"}), "firtp: t2=nan: not a finite number\n");
    EXPECT_EQ(with({"t2=0"}), "firtp: t2=0: stages=2 needs a positive time in seconds\n");
    EXPECT_EQ(with({"t2=-0.05"}), "firtp: t2=-0.05: stages=2 needs a positive time in seconds\n");
    EXPECT_EQ(with({"stages=3"}), "firtp: t3: stages=3 needs a positive time in seconds\n");
    EXPECT_EQ(with({"stages=5"}), "firtp: stages=5: must be 1 to 4\n");
    EXPECT_EQ(with({"t1=0.01", "t2=0.05"}), "firtp: t1..t4: filter times must not increase (T1 >= T2 >= ...)\n");
    EXPECT_EQ(with({"period_ns=0"}), "firtp: period_ns=0: must be positive\n");
    EXPECT_EQ(with({"t1=15", "t2=10"}),
              "firtp: t1..t4 and period_ns=1000000: the filter delay T1 + ... + Tn is longer than 20000 servo periods "
              "(20 s at 1 ms)\n");
    EXPECT_EQ(with({"period_ns=1000"}),
              "firtp: t1..t4 and period_ns=1000: the filter delay T1 + ... + Tn is longer than 20000 servo periods "
              "(20 s at 1 ms)\n");
    EXPECT_EQ(with({"max_velocity=300,x,300"}), "firtp: max_velocity=300,x,300: 'x' is not a finite number\n");
    EXPECT_EQ(with({"max_acceleration=5000,-1"}),
              "firtp: max_acceleration=5000,-1: '-1' must be zero (no limit) or positive\n");
    EXPECT_EQ(with({"max_jerk=1,2,3,4"}), "firtp: max_jerk=1,2,3,4: more values than axes=3\n");
    EXPECT_EQ(with({"max_jerk=1e5,,1e5"}), "firtp: max_jerk=1e5,,1e5: '' is not a finite number\n");
    EXPECT_EQ(with({"tolerance=0"}), "firtp: tolerance=0: must be positive\n");
    EXPECT_EQ(with({"tolerance=-0.05"}), "firtp: tolerance=-0.05: must be positive\n");
    EXPECT_EQ(with({"max_feed_override=0.5"}), "firtp: max_feed_override=0.5: must be at least 1 (100 %)\n");
    EXPECT_EQ(with({"rate_reserve=1"}),
              "firtp: rate_reserve=1: must lie between 0 and 1 (a share of the acceleration and jerk limits)\n");
    EXPECT_EQ(with({"queue=1"}), "firtp: queue=1: must be at least 2\n");
    EXPECT_EQ(with({"max_blocks=0"}), "firtp: max_blocks=0: must be at least 1\n");
    EXPECT_EQ(with({"plan_budget_us=-1"}), "firtp: plan_budget_us=-1: must be 0 (none) or positive\n");
    EXPECT_EQ(with({"axes=10"}), "firtp: axes=10: must be 1 to 9\n");
    EXPECT_EQ(with({"meaning=max"}), "firtp: meaning=max: must be corner or contour\n");
    EXPECT_EQ(with({"brake_speed=-1"}), "firtp: brake_speed=-1: must be zero or positive, units/s\n");
    EXPECT_EQ(with({"brake_speed=fast"}), "firtp: brake_speed=fast: not a finite number\n");
    EXPECT_EQ(with({"max_velocity=300,300,300", "max_acceleration=5000,5000,5000", "max_jerk=1e5,1e5,0"}), "loaded");
}

// A reload starts from the parameters' defaults. firtp.so stays mapped after dlclose (a C++ module
// with unique symbols cannot be unloaded), so its statics kept the last load's values: t3 kept a
// pointer into the string hal-shim had freed at unloadrt, and the next load without t3 read it
// (a use after free; this load failed with "t3=<garbage>"). hal-shim now restores every
// parameter it set before dlclose.
TEST(ModuleParams, ReloadStartsFromTheDefaults) {
    EXPECT_EQ(load({"stages=3", "t1=0.06", "t2=0.05", "t3=0.02", "block_key=0", "state_key=0", "queue=7"}), "loaded");
    EXPECT_EQ(load({"t1=0.06", "t2=0.05"}), "loaded");
    // The defaults are back: block_key and state_key create the streams the bridge attaches to.
    const shim::Status status = shim::load_module(firtp::default_module_path().string(), {"t1=0.06", "t2=0.05"});
    ASSERT_TRUE(status.ok()) << status.message;
    shim::Value queue_free;
    ASSERT_TRUE(shim::get_value("firtp.queue-free", queue_free).ok());
    EXPECT_EQ(queue_free.as_double(), 0.0);  // no period run yet; the pin exists
    std::vector<std::string> modules = shim::loaded_modules();
    EXPECT_EQ(modules, std::vector<std::string>{"firtp"});
    shim::unload_module("firtp");
}

// The same for the module's own state: a load with streams, then one without (block_key=0
// state_key=0). The second used to keep "has a block stream" from the first and read the destroyed
// stream in its first period (a segfault, found by the component-restart test).
TEST(ModuleParams, ReloadWithoutStreamsRunsWithoutTheOldOnes) {
    const std::string module = firtp::default_module_path().string();
    ASSERT_TRUE(shim::load_module(module, {"t1=0.06", "t2=0.05"}).ok());
    shim::unload_module("firtp");
    ASSERT_TRUE(shim::load_module(module, {"t1=0.06", "t2=0.05", "block_key=0", "state_key=0"}).ok());
    ASSERT_TRUE(shim::new_thread("servo-thread", 1000000).ok());
    ASSERT_TRUE(shim::add_funct("firtp.update", "servo-thread").ok());
    ASSERT_TRUE(shim::set_value("firtp.enable", "1").ok());
    ASSERT_TRUE(shim::step(10).ok());
    shim::Value tick;
    ASSERT_TRUE(shim::get_value("firtp.tick", tick).ok());
    EXPECT_EQ(tick.as_double(), 10.0);  // counted from this load
    shim::unload_module("firtp");
    shim::delete_thread("servo-thread");
}
