#include <firtp/host_command.hpp>

#include <firtp/gcode.hpp>
#include <firtp/host_report.hpp>
#include <firtp/messages.hpp>

#include <optional>
#include <vector>

#include <poll.h>

namespace firtp::host {
namespace {

using namespace std::chrono_literals;

// Applies one operator command; true when the operator wants to quit.
bool apply(const UiCommand& command, Host& host) {
    using Kind = UiCommand::Kind;
    const Progress progress = host.progress();
    switch (command.kind) {
        case Kind::feed_up: host.set_feed_scale(stepped_feed(progress.feed_request, 1, host.max_feed_scale())); break;
        case Kind::feed_down: host.set_feed_scale(stepped_feed(progress.feed_request, -1, host.max_feed_scale())); break;
        case Kind::set_feed: host.set_feed_scale(command.value); break;
        case Kind::toggle_hold: host.hold(!progress.hold); break;
        case Kind::hold: host.hold(true); break;
        case Kind::resume: host.hold(false); break;
        case Kind::abort: host.abort(); break;
        case Kind::quit: host.abort(); return true;
    }
    return false;
}

// Sleeps until LCM or the operator has something, at most `timeout`.
void wait_for_input(int lcm_fd, int input_fd, std::chrono::milliseconds timeout) {
    pollfd fds[2] = {{lcm_fd, POLLIN, 0}, {input_fd, POLLIN, 0}};  // negative fds are ignored
    poll(fds, 2, static_cast<int>(timeout.count()));
}

int exit_status(Result result, bool recording_incomplete) {
    switch (result) {
        case Result::done: return recording_incomplete ? host_exit_failed : host_exit_done;
        case Result::lost: return host_exit_lost;
        default: return host_exit_failed;  // failed, aborted, quit before the abort was confirmed
    }
}

}  // namespace

int run_host_command(const HostCommandOptions& options) {
    const ProgramFeed program = options.read_program
                                    ? options.read_program()
                                    : feed_of(std::make_shared<const Program>(read_gcode(options.program, options.machine)));
    const std::unique_ptr<lcm::LCM> lcm = messages::open(options.url.empty() ? messages::default_url() : options.url);
    const bool recording = static_cast<bool>(options.record_axis_state);
    HostOptions host_options = options.host;
    host_options.on_axis_state = options.record_axis_state;
    std::vector<firtp_lcm::event_t> reached;  // shown by the UI after each step
    host_options.on_event_reached = [&reached](const firtp_lcm::event_t& e) { reached.push_back(e); };
    Host host(*lcm, program, host_options);

    const Clock::time_point started = Clock::now();
    Result result = Result::running;
    {
        TerminalUi ui(options.ui);
        std::optional<Clock::time_point> quit_by;  // set by 'q' or a signal
        for (;;) {
            result = host.step();
            for (const firtp_lcm::event_t& e : reached) ui.event(e);
            reached.clear();
            const Clock::time_point now = Clock::now();
            ui.show(host.progress(), now);
            if (result != Result::running || (quit_by && now >= *quit_by)) break;
            for (const UiCommand& command : ui.read_commands())
                if (apply(command, host) && !quit_by) quit_by = now + options.quit_grace;
            if (ui.interrupted() && !quit_by) {
                host.abort();
                quit_by = now + options.quit_grace;
            }
            wait_for_input(lcm->getFileno(), ui.input_fd(), 20ms);
        }
        ui.finish(host.progress());
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - started).count();

    if (recording && options.axis_states_done) options.axis_states_done();
    const std::string report = host_report(options.program.string(), host, result, seconds, recording);
    if (options.report) {
        std::fputs(report.c_str(), options.report);
        std::fflush(options.report);
    }
    return exit_status(result, recording && !host.axis_state_gap_text().empty());
}

}  // namespace firtp::host
