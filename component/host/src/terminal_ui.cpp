// TTY handling of the operator interface: raw keys, command lines, the live progress line, and
// SIGINT/SIGTERM (the first restores the terminal and asks to quit, a second one kills).
#include <firtp/host_ui.hpp>

#include <atomic>
#include <csignal>

#include <poll.h>
#include <termios.h>
#include <unistd.h>

namespace firtp::host {
namespace {

// Shared with the signal handler; set before the handler is installed.
termios saved_termios{};
std::atomic<int> raw_fd{-1};       // fd in raw mode, -1 when none
std::atomic<int> interrupts{0};
struct sigaction old_int{}, old_term{};

extern "C" void on_interrupt(int signal_number) {
    const int fd = raw_fd.exchange(-1);
    if (fd >= 0) tcsetattr(fd, TCSANOW, &saved_termios);  // async-signal-safe
    if (interrupts.fetch_add(1) >= 1) {                   // second time: default action
        std::signal(signal_number, SIG_DFL);
        std::raise(signal_number);
    }
}

bool readable(int fd) {
    pollfd p{fd, POLLIN, 0};
    return poll(&p, 1, 0) > 0 && (p.revents & (POLLIN | POLLHUP)) != 0;
}

}  // namespace

TerminalUi::TerminalUi(UiOptions options) : options_(options), input_fd_(options.input_fd) {
    live_ = options_.output != nullptr && isatty(fileno(options_.output));
    interrupts = 0;
    if (input_fd_ >= 0 && isatty(input_fd_) && tcgetattr(input_fd_, &saved_termios) == 0) {
        termios raw = saved_termios;
        raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);  // ISIG stays: Ctrl-C still works
        raw.c_cc[VMIN] = 0;
        raw.c_cc[VTIME] = 0;
        raw_ = tcsetattr(input_fd_, TCSANOW, &raw) == 0;
        if (raw_) raw_fd = input_fd_;
    }
    struct sigaction action{};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int);
    sigaction(SIGTERM, &action, &old_term);
    if (raw_ && options_.output)
        std::fputs("keys: + / - feed override, space hold/resume, a abort, q abort and quit\n", options_.output);
}

TerminalUi::~TerminalUi() {
    restore_terminal();
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
}

void TerminalUi::restore_terminal() {
    const int fd = raw_fd.exchange(-1);
    if (fd >= 0) tcsetattr(fd, TCSANOW, &saved_termios);
}

bool TerminalUi::interrupted() const { return interrupts.load() > 0; }

std::vector<UiCommand> TerminalUi::read_commands() {
    std::vector<UiCommand> commands;
    if (input_fd_ < 0 || !readable(input_fd_)) return commands;
    char buffer[256];
    const ssize_t n = read(input_fd_, buffer, sizeof buffer);
    if (n <= 0) {
        if (n == 0 && !raw_) input_fd_ = -1;  // end of the command stream: keep running
        return commands;
    }
    const std::string_view text(buffer, static_cast<std::size_t>(n));
    if (raw_) {
        for (char key : text)
            if (auto command = command_for_key(key)) commands.push_back(*command);
        return commands;
    }
    pending_ += text;
    for (std::size_t end; (end = pending_.find('\n')) != std::string::npos; pending_.erase(0, end + 1)) {
        std::string error;
        if (auto command = parse_command_line(std::string_view(pending_).substr(0, end), error))
            commands.push_back(*command);
        else if (!error.empty() && options_.output)
            std::fprintf(options_.output, "%sfirtp host: %s\n", line_open_ ? "\n" : "", error.c_str());
        line_open_ = line_open_ && error.empty();
    }
    if (pending_.size() > 4096) pending_.clear();  // not a command stream
    return commands;
}

void TerminalUi::show(const Progress& progress, Clock::time_point now) {
    if (!options_.output) return;
    if (live_) {
        if (line_open_ && now - last_show_ < options_.refresh) return;
        last_show_ = now;
        std::fprintf(options_.output, "\r%s\033[K", progress_text(progress).c_str());
        std::fflush(options_.output);
        line_open_ = true;
        return;
    }
    if (progress.blocks == 0) return;
    const int decile = static_cast<int>(progress.executed * 10 / progress.blocks);
    if (decile <= printed_decile_) return;
    printed_decile_ = decile;
    std::fprintf(options_.output, "firtp host: %s\n", progress_text(progress).c_str());
    std::fflush(options_.output);
}

void TerminalUi::event(const firtp_lcm::event_t& event) {
    if (!options_.output) return;
    std::fprintf(options_.output, "%sfirtp host: %s\n", line_open_ ? "\r\033[K" : "", event_text(event).c_str());
    std::fflush(options_.output);
    line_open_ = false;  // the live line comes back at the next show()
}

void TerminalUi::finish(const Progress& progress) {
    if (!options_.output || !live_) return;
    std::fprintf(options_.output, "\r%s\033[K\n", progress_text(progress).c_str());
    std::fflush(options_.output);
    line_open_ = false;
}

}  // namespace firtp::host
