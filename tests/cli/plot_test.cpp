// --plot: a PNG drawn by gnuplot, renamed into place; skipped when gnuplot is not installed.
#include "cli_runner.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string_view>

#include <unistd.h>

namespace firtp::cli_test {
namespace {

constexpr std::string_view png_signature("\x89PNG\r\n\x1a\n", 8);

void expect_png(const std::filesystem::path& file) {
    const std::string png = read_file(file);
    EXPECT_GT(png.size(), 20000u);  // a 1200x1400 multiplot, not an empty canvas
    EXPECT_EQ(std::string_view(png).substr(0, 8), png_signature);
}

TEST(Plot, DiamondPng) {
    if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    TempDir dir;
    const Outcome r = run_firtp({"plan", example("diamond.ngc").string(), "--t1", "0.148", "--t2", "0.089", "--plot",
                                 (dir / "diamond.png").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;  // gnuplot printed no warning
    expect_png(dir / "diamond.png");
    EXPECT_EQ(dir.names(), std::set<std::string>{"diamond.png"});  // no temporary left
}

// Quotes, blanks and backquotes in names reach gnuplot literally.
TEST(Plot, AwkwardFileNames) {
    if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    TempDir dir;
    const std::string program = "it's `x` \"a\" \\ corner.ngc";
    write_file(dir / program, "G21 G90 G64 P0.1\nF3000\nG1 X2.5\nG1 Y2.5\nM2\n");
    const std::string png = "plot 'of' \"it\" `x`.png";
    const Outcome r = run_firtp({"plan", (dir / program).string(), "--plot", (dir / png).string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    expect_png(dir / png);
    EXPECT_EQ(dir.names(), (std::set<std::string>{program, png}));
}

// A program that never moves still gives a readable plot, without gnuplot warnings.
TEST(Plot, ProgramWithoutMoves) {
    if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
    TempDir dir;
    write_file(dir / "idle.ngc", "G21 G90\nM2\n");
    const Outcome r = run_firtp({"plan", (dir / "idle.ngc").string(), "--plot", (dir / "idle.png").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    const std::string png = read_file(dir / "idle.png");
    EXPECT_EQ(std::string_view(png).substr(0, 8), png_signature);
}

}  // namespace
}  // namespace firtp::cli_test
