// run_host_command end to end on memq:// (no component there): reading, exit codes, report.
#include <firtp/gcode.hpp>
#include <firtp/host_command.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace firtp::host {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

struct HostCommandTest : ::testing::Test {
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("firtp-host-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                 "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::FILE* report = std::tmpfile();
    std::FILE* progress = std::tmpfile();
    HostCommandOptions options;

    void SetUp() override {
        std::filesystem::create_directories(dir);
        options.url = "memq://";
        options.host.status_timeout = 100ms;
        options.ui = UiOptions{-1, progress};
        options.report = report;
    }
    void TearDown() override {
        std::fclose(report);
        std::fclose(progress);
        std::filesystem::remove_all(dir);
    }
    std::filesystem::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    }
    static std::string contents(std::FILE* file) {
        std::fflush(file);
        std::rewind(file);
        std::string text;
        for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
        return text;
    }
};

TEST_F(HostCommandTest, EmptyProgramIsDone) {
    options.program = write("empty.ngc", "G21 G90\nM2\n");
    bool saved = false;
    int states = 0;
    options.record_axis_state = [&](const firtp_lcm::axis_state_t&) { ++states; };
    options.axis_states_done = [&] { saved = true; };
    EXPECT_EQ(run_host_command(options), host_exit_done);
    EXPECT_TRUE(saved);
    EXPECT_EQ(states, 0);
    EXPECT_THAT(contents(report), HasSubstr("empty.ngc: done"));
}

TEST_F(HostCommandTest, NoComponentIsLostContact) {
    options.program = write("line.ngc", "G21 G90\nG1 X10 F600\nM2\n");
    EXPECT_EQ(run_host_command(options), host_exit_lost);
    const std::string text = contents(report);
    EXPECT_THAT(text, HasSubstr("line.ngc: lost contact"));
    EXPECT_THAT(text, HasSubstr("error: no status from the component for 100 ms"));
}

TEST_F(HostCommandTest, BadProgramThrows) {
    options.program = write("bad.ngc", "G1 X\n");
    EXPECT_THROW(run_host_command(options), GcodeError);
}

TEST_F(HostCommandTest, ExitCodesAreDistinct) {
    EXPECT_EQ(host_exit_done, 0);
    EXPECT_EQ(host_exit_failed, 1);
    EXPECT_EQ(host_exit_lost, 3);
}

}  // namespace
}  // namespace firtp::host
