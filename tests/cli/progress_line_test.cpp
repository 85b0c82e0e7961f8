// The progress line: drawn on a terminal (a pseudo-terminal here), never into a pipe, at most a
// few times a second, cleared at the end; and `firtp plan` draws it on a terminal's stderr only.
#include "cli_runner.hpp"
#include "progress_line.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <sstream>
#include <string>
#include <thread>

namespace firtp::cli {
namespace {

// Everything readable on `fd` now (non-blocking).
std::string drain(int fd) {
    std::string out;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0) return out;
        out.append(buffer, static_cast<std::size_t>(n));
    }
}

struct Pty {
    int master = -1, slave = -1;
    Pty() {
        if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) return;
        ::fcntl(master, F_SETFL, O_NONBLOCK);
    }
    ~Pty() {
        if (master >= 0) ::close(master);
        if (slave >= 0) ::close(slave);
    }
};

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(ProgressLine, DrawsOnATerminalAndClearsAtTheEnd) {
    Pty pty;
    if (pty.master < 0) GTEST_SKIP() << "no pseudo-terminal here";
    {
        ProgressLine line("plan", 67000, pty.slave, std::chrono::nanoseconds(0));
        EXPECT_TRUE(line.active());
        for (int i = 0; i < 1000; ++i) line.update(12345, 1234.56);
    }
    const std::string shown = drain(pty.master);
    EXPECT_NE(shown.find("\rplan: 12,345 / 67,000 blocks, program 1234.6 s, elapsed "), std::string::npos) << shown;
    EXPECT_EQ(shown.substr(shown.size() - 4), "\r\x1b[K");  // cleared
}

TEST(ProgressLine, NothingIntoAPipe) {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
    {
        ProgressLine line("plan", 10, fds[1], std::chrono::nanoseconds(0));
        EXPECT_FALSE(line.active());
        for (int i = 0; i < 1000; ++i) line.update(5, 1.0);
    }
    ::close(fds[1]);
    EXPECT_EQ(drain(fds[0]), "");
    ::close(fds[0]);
}

TEST(ProgressLine, AtMostOnceAnInterval) {
    Pty pty;
    if (pty.master < 0) GTEST_SKIP() << "no pseudo-terminal here";
    const auto interval = std::chrono::milliseconds(100);
    const auto start = std::chrono::steady_clock::now();
    {
        ProgressLine line("run", 10, pty.slave, interval);
        while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(450)) line.update(1, 0.1);
    }
    const std::string shown = drain(pty.master);
    EXPECT_GE(count(shown, "run: "), 1u);
    EXPECT_LE(count(shown, "run: "), 4u);  // 450 ms at one line per 100 ms at most
}

// firtp plan with stderr on a terminal: the line shows while planning and is gone at the end.
TEST(ProgressLine, FirtpPlanOnATerminal) {
    Pty pty;
    if (pty.master < 0) GTEST_SKIP() << "no pseudo-terminal here";
    // Long enough to plan that the line shows (its first draw comes after 250 ms): 4,000 s of
    // samples. (At F600, 1,000 s, planning got fast enough to end before the first draw: 0.3 s.)
    cli_test::TempDir dir;
    std::ostringstream text;
    text << "G21 G90 G64 P0.05\nG1 F150\n";
    for (int i = 1; i <= 20000; ++i) text << "X" << i * 0.5 << " Y" << (i % 2) * 0.2 << "\n";
    text << "M2\n";
    cli_test::write_file(dir / "long.ngc", text.str());
    const std::string program = (dir / "long.ngc").string();
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(pty.slave, 2);
        ::execl(FIRTP_BIN, FIRTP_BIN, "plan", program.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(pty.slave);
    pty.slave = -1;
    std::string shown;
    int status = 0;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
        shown += drain(pty.master);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    shown += drain(pty.master);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_NE(shown.find("plan: "), std::string::npos) << shown;
    EXPECT_NE(shown.find(" / 20,000 blocks, program "), std::string::npos) << shown;
    EXPECT_EQ(shown.substr(shown.size() - 4), "\r\x1b[K");
}

// The same command into pipes (as every other test runs it): no progress on stderr.
TEST(ProgressLine, FirtpPlanIntoAPipe) {
    const cli_test::Outcome o = cli_test::run_firtp({"plan", cli_test::example("cam_contour.ngc").string()});
    EXPECT_EQ(o.exit_code, 0);
    EXPECT_EQ(o.err, "");
}

}  // namespace
}  // namespace firtp::cli
