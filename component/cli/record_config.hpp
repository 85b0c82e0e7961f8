// FIRTP_CONFIG: the machine and settings of a running component, so that a log carries them
// (`firtp serve` and `firtp run` publish it; `firtp replay` rebuilds the component from it).
#pragma once

#include "component_options.hpp"

#include <firtp/machine.hpp>
#include <firtp/messages.hpp>
#include <firtp/in_process_component.hpp>

#include <chrono>
#include <span>
#include <string>

namespace firtp::cli {

// firtp.so's settings as `firtp serve` runs it: planning within half the servo period, `queue` blocks.
InProcessSettings serve_component_settings(const MachineConfig& machine, int queue);

// The message for `firtp COMMAND args...` running `machine` with `settings` (reads the INI's text).
firtp_lcm::config_t config_message(const std::string& command, std::span<const std::string> args,
                                   const ComponentOptions& options, const MachineConfig& machine,
                                   const InProcessSettings& settings);

// Publishes the message now and then every `every`, each time with the next seq.
class ConfigPublisher {
public:
    ConfigPublisher(lcm::LCM& lcm, firtp_lcm::config_t message,
                    std::chrono::milliseconds every = std::chrono::milliseconds(1000));
    void poll();  // publishes when due

private:
    void publish();
    lcm::LCM* lcm_;
    firtp_lcm::config_t message_;
    std::chrono::milliseconds every_;
    std::chrono::steady_clock::time_point last_;
};

// The component a config describes, rebuilt as its sender built it: the sender's command line
// parsed again, its INI read from the logged text (errors name the logged file name).
struct LoggedComponent {
    MachineConfig machine;
    InProcessSettings settings;
    std::string description;  // "firtp serve --ini diamond.ini (firtp 0.1.0)"
};
LoggedComponent component_from(const firtp_lcm::config_t& config);

}  // namespace firtp::cli
