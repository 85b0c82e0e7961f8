// The component side of firtp in this process: hal-shim runs firtp.so on a servo thread and
// firtp-bridge connects it to LCM, netted as a LinuxCNC HAL file would net them.
#pragma once

#include <firtp/bridge.hpp>
#include <firtp/defaults.hpp>
#include <firtp/machine.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace firtp {

// $FIRTP_MODULE, else firtp.so next to this program: installed ../lib/firtp/firtp.so, built ../lib/firtp.so.
std::filesystem::path default_module_path();

// firtp.so settings beyond the machine's (loadrt firtp queue=... max_blocks=...).
struct InProcessSettings {
    int queue = defaults::queue;            // blocks the component holds
    int max_blocks = defaults::max_blocks;  // stream blocks planned per servo period at most
    int plan_budget_us = 0;  // and only within this planning time (0: no limit, for stepped runs)
    int stream_depth = defaults::stream_depth;  // records the block stream holds: with queue, how far ahead a host may send
};

// firtp.so's machine as loadrt arguments, all but InProcessSettings' (axes=3 period_ns=...
// tolerance=... max_velocity=...), and the two numbers the chain needs from them.
struct ModuleMachine {
    int axes = 3;
    double period = defaults::servo_period;  // s
    std::vector<std::string> arguments;
};

// A machine's planner settings, exactly (shortest text that reads back as the same double).
ModuleMachine module_machine(const MachineConfig& machine);

class InProcessComponent {
public:
    // Loads firtp.so with the machine's settings, creates the bridge and nets them. Throws
    // std::runtime_error naming the step that failed.
    InProcessComponent(lcm::LCM& lcm, const MachineConfig& machine, const std::filesystem::path& module,
               const InProcessSettings& settings = {});
    // The same with firtp.so's loadrt arguments given (e.g. as LinuxCNC loaded it, from a log).
    InProcessComponent(lcm::LCM& lcm, const ModuleMachine& machine, const std::filesystem::path& module,
               const InProcessSettings& settings = {});
    ~InProcessComponent();
    InProcessComponent(const InProcessComponent&) = delete;
    InProcessComponent& operator=(const InProcessComponent&) = delete;

    // The bridge unloaded and loaded again while firtp.so runs on (in LinuxCNC: halcmd unload
    // firtp-lcm-bridge, then lcm.hal again): its pins leave their signals, which keep their
    // values, and the new bridge's join them; firtp.so runs `periods_between` periods alone.
    // net_at_once false: the new bridge's pins stay apart until net_bridge() (lcm.hal's net lines
    // run after loadusr -W, while the bridge already takes messages).
    void restart_bridge(int periods_between = 0, bool net_at_once = true);
    void net_bridge();
    void step();   // one servo period in this thread (deterministic, no clock)
    void start();  // or: the servo thread on the real-time clock
    void poll();   // the bridge's non-real-time work: axis states and status out
    Bridge& bridge() { return *bridge_; }
    // Last run time of firtp.update, ns (hal-shim's firtp.update.time).
    long update_time_ns() const;

private:
    lcm::LCM* lcm_;
    BridgeOptions bridge_options_;
    std::unique_ptr<Bridge> bridge_;
    bool started_ = false;
};

}  // namespace firtp
