// FIRTP_CONFIG: the machine and settings of a running component, so that a log carries them
// (`firtp serve` and `firtp run` publish it; `firtp replay` rebuilds the component from it).
#pragma once

#include "component_options.hpp"

#include <firtp/machine.hpp>
#include <firtp/config_publisher.hpp>
#include <firtp/messages.hpp>
#include <firtp/in_process_component.hpp>

#include <span>
#include <string>

namespace firtp::cli {

// firtp.so's settings as `firtp serve` runs it: planning within half the servo period, `queue` blocks.
InProcessSettings serve_component_settings(const MachineConfig& machine, int queue);

// The message for `firtp COMMAND args...` running `machine` with `settings` (reads the INI's text).
firtp_lcm::config_t config_message(const std::string& command, std::span<const std::string> args,
                                   const ComponentOptions& options, const MachineConfig& machine,
                                   const InProcessSettings& settings);

using messages::ConfigPublisher;  // publishes it now and every second

// The component a config describes, rebuilt as its sender built it: for "serve" and "run" the
// sender's command line parsed again, its INI read from the logged text (errors name the logged
// file name); for "loadrt" (firtp.so in LinuxCNC, firtp-lcm-bridge) firtp.so's logged loadrt words.
struct LoggedComponent {
    ModuleMachine machine;
    InProcessSettings settings;
    std::string description;  // "firtp serve --ini diamond.ini (firtp 0.1.0)"
};
LoggedComponent component_from(const firtp_lcm::config_t& config);

}  // namespace firtp::cli
