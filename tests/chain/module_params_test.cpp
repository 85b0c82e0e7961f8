// firtp.so refuses bad module parameters at load (loadrt firtp ...), printing a message that
// names the parameter: not numbers, zero or negative where positive is needed, NaN, limits lists,
// filter times the planner cannot be built for. Loaded through hal-shim as firtp-hal does.
#include <firtp/hal_shim/runtime.hpp>
#include <firtp/servo_chain.hpp>
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
