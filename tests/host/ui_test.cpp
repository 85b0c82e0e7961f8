// Operator interface: keys, command lines, feed steps, progress text, non-TTY input and output.
#include <firtp/host_ui.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace firtp::host {
namespace {

using Kind = UiCommand::Kind;
using ::testing::HasSubstr;

TEST(UiKeys, MapToCommands) {
    EXPECT_EQ(command_for_key('+')->kind, Kind::feed_up);
    EXPECT_EQ(command_for_key('=')->kind, Kind::feed_up);
    EXPECT_EQ(command_for_key('-')->kind, Kind::feed_down);
    EXPECT_EQ(command_for_key(' ')->kind, Kind::toggle_hold);
    EXPECT_EQ(command_for_key('a')->kind, Kind::abort);
    EXPECT_EQ(command_for_key('q')->kind, Kind::quit);
    EXPECT_FALSE(command_for_key('x'));
}

TEST(UiCommandLines, Parse) {
    std::string error;
    auto feed = parse_command_line("  feed 0.8 \r", error);
    ASSERT_TRUE(feed);
    EXPECT_EQ(feed->kind, Kind::set_feed);
    EXPECT_EQ(feed->value, 0.8);
    EXPECT_EQ(parse_command_line("hold", error)->kind, Kind::hold);
    EXPECT_EQ(parse_command_line("resume", error)->kind, Kind::resume);
    EXPECT_EQ(parse_command_line("abort", error)->kind, Kind::abort);
    EXPECT_EQ(parse_command_line("quit", error)->kind, Kind::quit);
    EXPECT_FALSE(parse_command_line("", error));
    EXPECT_EQ(error, "");
    EXPECT_FALSE(parse_command_line("# comment", error));
    EXPECT_EQ(error, "");
}

TEST(UiCommandLines, RejectBadInput) {
    std::string error;
    EXPECT_FALSE(parse_command_line("fed 1", error));
    EXPECT_THAT(error, HasSubstr("unknown command 'fed'"));
    EXPECT_FALSE(parse_command_line("feed", error));
    EXPECT_THAT(error, HasSubstr("feed needs a number"));
    EXPECT_FALSE(parse_command_line("feed -1", error));
    EXPECT_FALSE(parse_command_line("feed 0.8x", error));
    EXPECT_FALSE(parse_command_line("feed nan", error));
    EXPECT_FALSE(parse_command_line("hold now", error));
    EXPECT_THAT(error, HasSubstr("takes no argument"));
}

TEST(UiFeed, StepsOfTenPercentClamped) {
    EXPECT_DOUBLE_EQ(stepped_feed(1.0, 1, 1.5), 1.1);
    EXPECT_DOUBLE_EQ(stepped_feed(1.0, -1, 1.5), 0.9);
    EXPECT_DOUBLE_EQ(stepped_feed(1.5, 1, 1.5), 1.5);
    EXPECT_DOUBLE_EQ(stepped_feed(0.0, -1, 1.5), 0.0);
    EXPECT_DOUBLE_EQ(stepped_feed(0.83, 1, 1.5), 0.9);  // back on the grid
    EXPECT_DOUBLE_EQ(stepped_feed(1.2, 1, 1.25), 1.25);
}

TEST(UiProgress, Text) {
    Progress p;
    p.blocks = 120;
    p.acknowledged = 54;
    p.executed = 48;
    p.line = 57;
    p.state = 1;
    p.feed_in_effect = 0.8;
    p.feed_request = 0.9;
    p.hold = true;
    EXPECT_EQ(progress_text(p),
              "acknowledged 45%, executed 40% (48/120 blocks), line 57, moving, feed 80% (asked 90%), hold requested");
    p = Progress{};
    EXPECT_EQ(progress_text(p), "acknowledged 100%, executed 100% (0/0 blocks), line 0, waiting, feed 100%");
}

struct Pipe {
    int fds[2] = {-1, -1};
    Pipe() { EXPECT_EQ(pipe(fds), 0); }
    ~Pipe() {
        for (int fd : fds)
            if (fd >= 0) close(fd);
    }
    void write_text(const std::string& text) { EXPECT_EQ(write(fds[1], text.data(), text.size()), ssize_t(text.size())); }
    void close_writer() {
        close(fds[1]);
        fds[1] = -1;
    }
};

std::string contents(std::FILE* file) {
    std::fflush(file);
    std::rewind(file);
    std::string text;
    for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
    return text;
}

TEST(TerminalUiTest, ReadsCommandLinesFromAPipe) {
    Pipe input;
    std::FILE* output = std::tmpfile();
    {
        TerminalUi ui(UiOptions{input.fds[0], output});
        EXPECT_FALSE(ui.raw_keys());
        EXPECT_TRUE(ui.read_commands().empty());  // nothing yet, and no blocking
        input.write_text("feed 0.8\nbogus\nho");
        auto commands = ui.read_commands();
        ASSERT_EQ(commands.size(), 1u);
        EXPECT_EQ(commands[0].kind, Kind::set_feed);
        input.write_text("ld\n");
        commands = ui.read_commands();
        ASSERT_EQ(commands.size(), 1u);
        EXPECT_EQ(commands[0].kind, Kind::hold);
        input.close_writer();
        EXPECT_TRUE(ui.read_commands().empty());
        EXPECT_EQ(ui.input_fd(), -1);  // end of input: nothing more to poll
    }
    EXPECT_THAT(contents(output), HasSubstr("firtp host: unknown command 'bogus'"));
    std::fclose(output);
}

TEST(UiEvents, Text) {
    firtp_lcm::event_t e{};
    e.line = 14;
    e.kind = firtp_lcm::event_t::TOOL_CHANGE;
    e.value = 2;
    EXPECT_EQ(event_text(e), "line 14: tool_change T2 reached");
    e.kind = firtp_lcm::event_t::SPINDLE_SPEED;
    e.value = 12000;
    EXPECT_EQ(event_text(e), "line 14: spindle_speed S12000 reached");
    e.kind = firtp_lcm::event_t::DWELL;
    e.value = 0.25;
    EXPECT_EQ(event_text(e), "line 14: dwell 0.25 s reached");
    e.kind = firtp_lcm::event_t::PAUSE;
    EXPECT_EQ(event_text(e), "line 14: pause reached");
}

TEST(TerminalUiTest, EachReachedEventOnALineOfItsOwn) {
    std::FILE* output = std::tmpfile();
    {
        TerminalUi ui(UiOptions{-1, output});
        firtp_lcm::event_t e{};
        e.line = 3;
        e.kind = firtp_lcm::event_t::FLOOD_ON;
        ui.event(e);
        e.line = 9;
        e.kind = firtp_lcm::event_t::PROGRAM_END;
        ui.event(e);
    }
    EXPECT_EQ(contents(output), "firtp host: line 3: flood_on reached\nfirtp host: line 9: program_end reached\n");
    std::fclose(output);
}

TEST(TerminalUiTest, OneLinePerTenPercentWhenNotATerminal) {
    std::FILE* output = std::tmpfile();
    {
        TerminalUi ui(UiOptions{-1, output});
        Progress p;
        p.blocks = 50;
        for (std::size_t executed = 0; executed <= 50; ++executed) {
            p.executed = p.acknowledged = executed;
            for (int repeat = 0; repeat < 3; ++repeat) ui.show(p, Clock::now());
        }
        ui.finish(p);
    }
    const std::string text = contents(output);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 10);
    EXPECT_THAT(text, HasSubstr("executed 10% (5/50 blocks)"));
    EXPECT_THAT(text, HasSubstr("executed 100% (50/50 blocks)"));
    std::fclose(output);
}

TEST(TerminalUiTest, FirstInterruptIsReportedNotFatal) {
    struct sigaction before{};
    sigaction(SIGINT, nullptr, &before);
    {
        TerminalUi ui(UiOptions{-1, nullptr});
        EXPECT_FALSE(ui.interrupted());
        std::raise(SIGINT);
        EXPECT_TRUE(ui.interrupted());
    }
    struct sigaction after{};
    sigaction(SIGINT, nullptr, &after);
    EXPECT_EQ(after.sa_handler, before.sa_handler);  // handler given back
}

}  // namespace
}  // namespace firtp::host
