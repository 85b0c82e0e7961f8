// Operator side of `firtp host`: a progress line on stderr and commands from stdin.
// Keys when stdin is a TTY (raw mode, restored on exit and on SIGINT/SIGTERM):
//   +  feed override +10 %     -  feed override -10 %     space  hold / resume
//   a  abort                   q  abort and quit
// Lines when stdin is not a TTY: "feed 0.8", "hold", "resume", "abort", "quit".
#pragma once

#include <firtp/host.hpp>

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace firtp::host {

struct UiCommand {
    enum class Kind { feed_up, feed_down, set_feed, toggle_hold, hold, resume, abort, quit };
    Kind kind;
    double value = 0.0;  // set_feed only
};

// '+' (or '='), '-', ' ', 'a', 'q'; nullopt for any other key.
std::optional<UiCommand> command_for_key(char key);

// One command line. nullopt with an empty `error` for a blank line or '#' comment, nullopt with
// `error` set for anything it does not know (e.g. "unknown command 'fed'").
std::optional<UiCommand> parse_command_line(std::string_view line, std::string& error);

// `current` moved `steps` 10 % steps on the 10 % grid, clamped to 0 .. max_feed.
double stepped_feed(double current, int steps, double max_feed);

// "acknowledged 45%, executed 40% (48/120 blocks), line 57, moving, feed 100%".
std::string progress_text(const Progress& progress);

// "line 14: tool_change T2 reached" (kinds as `firtp plan` names them; rpm, tool or seconds).
std::string event_text(const firtp_lcm::event_t& event);

struct UiOptions {
    int input_fd = 0;                       // -1: no operator input
    std::FILE* output = stderr;             // progress; a TTY gets a live line
    std::chrono::milliseconds refresh{100}; // live line at most this often
};

// One at a time: it owns the SIGINT/SIGTERM handlers while it lives.
class TerminalUi {
public:
    explicit TerminalUi(UiOptions options = {});
    ~TerminalUi();
    TerminalUi(const TerminalUi&) = delete;
    TerminalUi& operator=(const TerminalUi&) = delete;

    int input_fd() const { return input_fd_; }  // to poll; -1 once there is nothing to read
    bool raw_keys() const { return raw_; }      // stdin is a TTY in raw mode
    std::vector<UiCommand> read_commands();     // what is available now; never blocks
    bool interrupted() const;                   // SIGINT or SIGTERM arrived (a second one kills)

    // Live line on a TTY (rate-limited); otherwise one line per 10 % of blocks executed.
    void show(const Progress& progress, Clock::time_point now);
    void finish(const Progress& progress);      // ends the live line
    void event(const firtp_lcm::event_t& event);  // a line of its own (event_text)

private:
    void restore_terminal();

    UiOptions options_;
    int input_fd_;
    bool raw_ = false;
    bool live_ = false;        // output is a TTY
    bool line_open_ = false;   // a live line without its newline is on screen
    Clock::time_point last_show_{};
    int printed_decile_ = 0;
    std::string pending_;      // partial command line
};

}  // namespace firtp::host
