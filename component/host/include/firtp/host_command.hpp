// `firtp host PROGRAM.ngc`: read the program, stream it to the component over LCM with the
// terminal UI until it is done, failed, aborted or contact is lost, then print a report.
#pragma once

#include <firtp/host.hpp>
#include <firtp/host_ui.hpp>
#include <firtp/machine.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace firtp::host {

// Exit status of run_host_command.
constexpr int host_exit_done = 0;    // every block executed (and the recording, if any, is complete)
constexpr int host_exit_failed = 1;  // component error, block never accepted, operator abort/quit,
                                     // or axis-state messages lost while recording
constexpr int host_exit_lost = 3;    // no status from the component for host.status_timeout

struct HostCommandOptions {
    std::filesystem::path program;              // PROGRAM.ngc
    // The program as read elsewhere (`firtp host`: spooled to a temporary file, so that memory does
    // not grow with it); empty: read_gcode(program, machine), kept in memory.
    std::function<ProgramFeed()> read_program;
    MachineConfig machine = default_machine();  // feed caps for the G-code reader
    std::string url;                            // LCM URL; "" -> messages::default_url()
    HostOptions host;                           // timeouts, initial and maximum feed override
    UiOptions ui;                               // stdin keys / commands, stderr progress
    std::FILE* report = stdout;                 // final report
    std::chrono::milliseconds quit_grace{1000}; // 'q': wait this long for the abort to be confirmed
    // Set to record every FIRTP_AXIS_STATE message (e.g. for --csv): each as it arrives, in arrival
    // order (nothing is kept here); then axis_states_done, if set, once at the end whatever the result.
    std::function<void(const firtp_lcm::axis_state_t&)> record_axis_state;
    std::function<void()> axis_states_done;
};

// Returns one of the exit statuses above. Throws what read_gcode or read_program (GcodeError) and
// messages::open (std::runtime_error) throw: bad program, no LCM transport.
int run_host_command(const HostCommandOptions& options);

}  // namespace firtp::host
