#include "progress_line.hpp"

#include "number_text.hpp"

#include <unistd.h>

namespace firtp::cli {
namespace {

constexpr unsigned clock_every = 64;  // updates between looks at the clock

// 67000 -> "67,000"
std::string grouped(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

void write_all(int fd, const std::string& text) {
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n <= 0) return;  // a progress line is not worth an error
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

ProgressLine::ProgressLine(std::string label, std::size_t total_blocks, int fd, Clock::duration interval)
    : label_(std::move(label)), total_(total_blocks), fd_(fd), interval_(interval), active_(::isatty(fd) == 1),
      start_(Clock::now()), next_(start_ + interval) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::update(std::size_t blocks_done, double program_time) {
    if (!active_ || ++calls_ % clock_every != 0) return;
    const Clock::time_point now = Clock::now();
    if (now < next_) return;
    next_ = now + interval_;
    draw(blocks_done, program_time, now);
}

void ProgressLine::draw(std::size_t blocks_done, double program_time, Clock::time_point now) {
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // \r: back to the line's start; ESC [K: erase what a longer earlier line left.
    write_all(fd_, "\r" + label_ + ": " + grouped(blocks_done) + " / " + grouped(total_) + " blocks, program " +
                       fixed_text(program_time, 1) + " s, elapsed " + fixed_text(elapsed, 1) + " s\x1b[K");
    drawn_ = true;
}

void ProgressLine::clear() {
    if (active_ && drawn_) write_all(fd_, "\r\x1b[K");
    active_ = false;
}

}  // namespace firtp::cli
