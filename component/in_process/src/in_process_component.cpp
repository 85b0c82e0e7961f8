#include <firtp/in_process_component.hpp>


#include <firtp/loadrt_number.hpp>
#include <firtp/text_cat.hpp>

#include <firtp/hal_shim/runtime.hpp>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace firtp {
namespace {

namespace shim = firtp::hal_shim;

void check(const shim::Status& status, const std::string& what) {
    if (!status.ok()) throw std::runtime_error(cat(what, ": ", status.message));
}

// loadrt arguments for the settings beyond the machine's.
std::vector<std::string> settings_arguments(const InProcessSettings& settings) {
    return {
        cat("queue=", std::to_string(settings.queue)),
        cat("max_blocks=", std::to_string(settings.max_blocks)),
        cat("plan_budget_us=", std::to_string(settings.plan_budget_us)),
        cat("stream_depth=", std::to_string(settings.stream_depth)),
    };
}

}  // namespace

ModuleMachine module_machine(const MachineConfig& machine) {
    const PlannerParameters p = machine.planner_parameters();
    ModuleMachine m;
    m.axes = machine.limits.axes;
    m.period = machine.period;
    m.arguments = {
        cat("axes=", std::to_string(machine.limits.axes)),
        cat("tolerance=", loadrt_number(machine.default_tolerance)),
        cat("meaning=", to_string(p.tolerance_meaning)),
        cat("period_ns=", std::to_string(std::llround(p.period * 1e9))),
        cat("max_feed_override=", loadrt_number(p.max_rate)),
        cat("rate_reserve=", loadrt_number(p.rate_reserve)),
    };
    if (p.fixed_chain) {  // the paper's chain; without t1 firtp.so smooths at the limits below
        m.arguments.push_back(cat("stages=", std::to_string(p.filters.stages)));
        for (int i = 0; i < p.filters.stages; ++i)
            m.arguments.push_back(cat("t", std::to_string(i + 1), "=", loadrt_number(p.filters.T[i])));
    }
    auto per_axis = [&](const char* name, double AxisLimits::*limit) {
        std::string list;
        for (int a = 0; a < p.limits.axes; ++a) list += cat(a ? "," : "", loadrt_number(p.limits.axis[a].*limit));
        m.arguments.push_back(cat(name, "=", list));
    };
    per_axis("max_velocity", &AxisLimits::max_velocity);
    per_axis("max_acceleration", &AxisLimits::max_acceleration);
    per_axis("max_jerk", &AxisLimits::max_jerk);
    return m;
}

std::filesystem::path default_module_path() {
    if (const char* path = std::getenv("FIRTP_MODULE")) return path;
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return "firtp.so";
    // installed: PREFIX/bin/firtp -> PREFIX/lib/firtp/firtp.so; in the build tree: build/lib/firtp.so
    const std::filesystem::path lib = self.parent_path().parent_path() / "lib";
    return std::filesystem::exists(lib / "firtp" / "firtp.so", error) ? lib / "firtp" / "firtp.so" : lib / "firtp.so";
}

InProcessComponent::InProcessComponent(lcm::LCM& lcm, const MachineConfig& machine, const std::filesystem::path& module,
                       const InProcessSettings& settings)
    : InProcessComponent(lcm, module_machine(machine), module, settings) {}

InProcessComponent::InProcessComponent(lcm::LCM& lcm, const ModuleMachine& machine, const std::filesystem::path& module,
                       const InProcessSettings& settings)
    : lcm_(&lcm) {
    const long period_ns = std::lround(machine.period * 1e9);
    check(shim::load_module("threads", {"name1=servo-thread", cat("period1=", std::to_string(period_ns))}),
          "creating the servo thread");
    if (!std::filesystem::exists(module))
        throw std::runtime_error(cat("the firtp HAL component '", module.string(),
                                     "' does not exist (build it, or give --module / $FIRTP_MODULE)"));
    std::vector<std::string> arguments = machine.arguments;
    for (std::string& word : settings_arguments(settings)) arguments.push_back(std::move(word));
    check(shim::load_module(module.string(), arguments), cat("loadrt ", module.string()));
    bridge_options_.axes = machine.axes;
    bridge_options_.period = machine.period;
    bridge_ = std::make_unique<Bridge>(lcm, bridge_options_);
    net_bridge();
    // Nobody changes tools and no operator resumes here: the handshakes are looped back (a tool
    // change and a pause take a servo period).
    check(shim::net("tool-change-loop", {"firtp.tool-change", "firtp.tool-changed"}), "net firtp.tool-change firtp.tool-changed");
    check(shim::net("pause-loop", {"firtp.paused", "firtp.resume"}), "net firtp.paused firtp.resume");
    check(shim::set_value("firtp.enable", "1"), "setp firtp.enable 1");
    check(shim::add_funct("firtp.update", "servo-thread"), "addf firtp.update servo-thread");
}

void InProcessComponent::net_bridge() {
    for (const char* const* pair = Bridge::pin_pairs(); pair[0]; pair += 2) {
        const std::string bridge_pin = pair[0], component_pin = pair[1];
        check(shim::net(cat(bridge_pin.substr(bridge_pin.find('.') + 1), "-net"), {bridge_pin, component_pin}),
              cat("net ", bridge_pin, " ", component_pin));
    }
}

void InProcessComponent::restart_bridge(int periods_between, bool net_at_once) {
    bridge_.reset();
    for (int k = 0; k < periods_between; ++k) step();
    bridge_ = std::make_unique<Bridge>(*lcm_, bridge_options_);
    if (net_at_once) net_bridge();
}

InProcessComponent::~InProcessComponent() {
    if (started_) shim::stop_threads();
    bridge_.reset();
    shim::unload_module("all");
    shim::delete_thread("servo-thread");  // so another chain can be built in this process
}

void InProcessComponent::step() { check(shim::step(1), "servo period"); }

void InProcessComponent::start() {
    check(shim::start_threads(), "starting the servo thread");
    started_ = true;
}

void InProcessComponent::poll() { bridge_->poll(); }

long InProcessComponent::update_time_ns() const {
    shim::Value value;
    return shim::get_value("firtp.update.time", value).ok() ? static_cast<long>(value.as_double()) : -1;
}

}  // namespace firtp
