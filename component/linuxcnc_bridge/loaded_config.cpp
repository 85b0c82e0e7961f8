#include "loaded_config.hpp"

#include <firtp/loadrt_number.hpp>
#include <firtp/version.hpp>

#include <hal.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace firtp {
namespace {

// firtp.so's HAL name (hal_init in component/hal/firtp.cpp)
constexpr const char* component = "firtp";

const hal_data_u& param(const std::string& name, hal_type_t type) {
    const std::string full = std::string(component) + "." + name;
    hal_type_t found{};
    hal_data_u* data = nullptr;
    if (hal_get_param_value_by_name(full.c_str(), &found, &data) != 0 || data == nullptr)
        throw std::runtime_error("no HAL param " + full + ": load firtp.so (loadrt firtp) before the bridge");
    if (found != type) throw std::runtime_error("HAL param " + full + " has another type than firtp.so's");
    return *data;
}

int s32(const std::string& name) { return param(name, HAL_S32).s; }
bool bit(const std::string& name) { return param(name, HAL_BIT).b; }

std::string number(const std::string& name) { return loadrt_number(param(name, HAL_FLOAT).f); }

void add(firtp_lcm::config_t& m, const std::string& word) { m.args.append(m.args.empty() ? "" : "\n").append(word); }

}  // namespace

firtp_lcm::config_t loaded_firtp_config() {
    firtp_lcm::config_t m{};
    m.sender = std::string("firtp-lcm-bridge ") + firtp::version;
    m.command = "loadrt";
    const int axes = s32("axes");
    add(m, "axes=" + std::to_string(axes));
    add(m, "period_ns=" + std::to_string(s32("period-ns")));
    add(m, "tolerance=" + number("tolerance"));
    add(m, bit("contour") ? "meaning=contour" : "meaning=corner");
    add(m, "max_feed_override=" + number("max-feed-override"));
    add(m, "rate_reserve=" + number("rate-reserve"));
    add(m, "brake_speed=" + number("brake-speed"));
    if (bit("fixed-chain")) {
        const int stages = s32("stages");
        add(m, "stages=" + std::to_string(stages));
        for (int i = 1; i <= stages; ++i) add(m, "t" + std::to_string(i) + "=" + number("t" + std::to_string(i)));
    }
    for (const char* limit : {"max-velocity", "max-acceleration", "max-jerk"}) {
        std::string word = limit;
        for (char& c : word) c = c == '-' ? '_' : c;
        word += "=";
        for (int a = 0; a < axes; ++a) {
            if (a > 0) word += ',';
            word += number("axis." + std::to_string(a) + "." + limit);
        }
        add(m, word);
    }
    m.queue = s32("queue");
    m.max_blocks = s32("max-blocks");
    m.stream_depth = s32("stream-depth");
    m.plan_budget_us = s32("plan-budget-us");
    m.period = s32("period-ns") * 1e-9;
    m.axes = axes;
    if (const char* ini = std::getenv("INI_FILE_NAME")) {  // for the reader; the args are the machine
        std::ifstream in(ini, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (in) {
            m.ini_file = ini;
            m.ini_text = text.str();
        }
    }
    return m;
}

}  // namespace firtp
