// A progress line for long work, on a terminal only: "plan: 12,345 / 67,000 blocks, program
// 1234.5 s, elapsed 12.3 s", redrawn in place at most every `interval` and cleared at the end.
// Where the stream is not a terminal (a pipe, a file, a test capturing it) it writes nothing.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace firtp::cli {

class ProgressLine {
public:
    using Clock = std::chrono::steady_clock;

    // fd: where to draw (stderr by default); shown only if isatty(fd).
    ProgressLine(std::string label, std::size_t total_blocks, int fd = 2,
                 Clock::duration interval = std::chrono::milliseconds(250));
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;
    ~ProgressLine();  // clear()

    // Cheap to call every servo period: looks at the clock once in a while and redraws when due.
    void update(std::size_t blocks_done, double program_time);
    // Removes the line (once); later updates draw nothing.
    void clear();

    bool active() const { return active_; }

private:
    void draw(std::size_t blocks_done, double program_time, Clock::time_point now);

    std::string label_;
    std::size_t total_;
    int fd_;
    Clock::duration interval_;
    bool active_;
    bool drawn_ = false;
    unsigned calls_ = 0;
    Clock::time_point start_;
    Clock::time_point next_;
};

}  // namespace firtp::cli
