// Bad programs, INI files and flags: "firtp: file:line[:column]: message" on stderr, exit 1 or 2,
// and none of the requested output files (nor a temporary) left behind.
#include "cli_runner.hpp"

#include <gtest/gtest.h>

namespace firtp::cli_test {
namespace {

struct Failure {
    Outcome outcome;
    std::set<std::string> left;  // directory entries after the run
};

// Runs plan on `program` written into a fresh directory, asking for all three outputs.
Failure plan_in_dir(const std::string& program, const std::vector<std::string>& flags,
                    const std::optional<std::string>& path_env = std::nullopt) {
    TempDir dir;
    write_file(dir / "prog.ngc", program);
    std::vector<std::string> args{"plan", (dir / "prog.ngc").string(), "--csv", (dir / "out.csv").string(),
                                  "--json", (dir / "out.json").string(), "--plot", (dir / "out.png").string()};
    args.insert(args.end(), flags.begin(), flags.end());
    Failure failure{run_firtp(args, path_env), {}};
    failure.left = dir.names();
    failure.left.erase("prog.ngc");
    failure.left.erase("machine.ini");
    return failure;
}

struct BadProgram {
    const char* name;
    const char* text;
    const char* where;    // ":line:column:" expected after the file name
    const char* message;  // part of the message
};

void PrintTo(const BadProgram& p, std::ostream* out) { *out << p.name; }

class BadGcode : public testing::TestWithParam<BadProgram> {};

// LinuxCNC's interpreter refuses them; firtp names the file and line with LinuxCNC's reason.
TEST_P(BadGcode, NamesLineAndWritesNothing) {
    const BadProgram& p = GetParam();
    const Failure f = plan_in_dir(p.text, {});
    EXPECT_EQ(f.outcome.exit_code, 1);
    EXPECT_NE(f.outcome.err.find(std::string("prog.ngc") + p.where), std::string::npos) << f.outcome.err;
    EXPECT_EQ(f.outcome.err.rfind("firtp: ", 0), 0u) << f.outcome.err;
    EXPECT_NE(f.outcome.err.find(p.message), std::string::npos) << f.outcome.err;
    EXPECT_TRUE(f.left.empty()) << *f.left.begin();
    EXPECT_TRUE(f.outcome.out.empty()) << f.outcome.out;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadGcode,
    testing::Values(BadProgram{"UnknownGCode", "G21 G90\nG1 X1 F100\nG5 X2\nM2\n", ":3: ", "Must specify both P and Q with G5"},
                    BadProgram{"MalformedNumber", "G21\nG1 X1..5 F100\nM2\n", ":2: ", "bad number format (trailing characters) parsing '1..5'"},
                    BadProgram{"FeedMissing", "G21 G90\nG1 X10\nM2\n", ":2: ", "Cannot do g1 with zero feed rate"},
                    BadProgram{"UnclosedComment", "G21\nG1 X1 F100 (note\nM2\n", ":2: ", "Unclosed comment found"},
                    BadProgram{"UnknownWord", "G21\nG1 X1 Q5 F100\nM2\n", ":2: ", "Q word with no G5, G10, G64"}),
    [](const testing::TestParamInfo<BadProgram>& test) { return std::string(test.param.name); });

constexpr const char* good_program = "G21 G90 G64 P0.1\nF3000\nG1 X2.5\nG1 Y2.5\nM2\n";

TEST(BadInput, IniValueNamesFileLineAndKey) {
    TempDir dir;
    write_file(dir / "machine.ini", "[AXIS_X]\nMAX_VELOCITY = 300\nMAX_ACCELERATION = fast\n");
    write_file(dir / "prog.ngc", good_program);
    const Outcome r = run_firtp({"plan", (dir / "prog.ngc").string(), "--ini", (dir / "machine.ini").string(),
                                 "--csv", (dir / "out.csv").string(), "--json", (dir / "out.json").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("machine.ini:3:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("MAX_ACCELERATION"), std::string::npos) << r.err;
    EXPECT_EQ(dir.names(), (std::set<std::string>{"machine.ini", "prog.ngc"}));
}

// [FIRTP]MAX_PROGRAM_BLOCKS: an arc whose chords take the program beyond it, named, nothing written.
TEST(BadInput, ProgramBeyondMaxProgramBlocksNamesTheLine) {
    TempDir dir;
    write_file(dir / "machine.ini", "[FIRTP]\nMAX_PROGRAM_BLOCKS = 100\n");
    write_file(dir / "prog.ngc", "G1 F600 X10\nG2 X10 Y0 I-10 J0\nM2\n");
    const Outcome r = run_firtp({"plan", (dir / "prog.ngc").string(), "--ini", (dir / "machine.ini").string(),
                                 "--csv", (dir / "out.csv").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "firtp: " + (dir / "prog.ngc").string() +
                         ":2: the program needs more than 100 blocks ([FIRTP]MAX_PROGRAM_BLOCKS = 100): this arc's "
                         "229 chords come after 1 block (a coarser [FIRTP]ARC_CHORD_TOLERANCE needs fewer)\n");
    EXPECT_EQ(dir.names(), (std::set<std::string>{"machine.ini", "prog.ngc"}));
}

// A lathe ([TRAJ]COORDINATES = X Z) has no Y: a program that moves Y is refused at that line by
// `plan` and by `run`, whose component and LCM log are under way by then; nothing is left behind.
TEST(BadInput, MoveOfAnAxisTheMachineDoesNotHaveNamesTheLine) {
    for (const char* command : {"plan", "run"}) {
        SCOPED_TRACE(command);
        TempDir dir;
        write_file(dir / "machine.ini", "[TRAJ]\nCOORDINATES = X Z\n[AXIS_X]\nMAX_ACCELERATION = 1000\n"
                                        "[AXIS_Z]\nMAX_ACCELERATION = 1000\n");
        write_file(dir / "prog.ngc", "G21 G90 G64 P0.1\nF600\nG1 X2\nG1 Z-1\nG1 Y1\nM2\n");
        std::vector<std::string> args{command, (dir / "prog.ngc").string(), "--ini", (dir / "machine.ini").string(),
                                      "--csv", (dir / "out.csv").string(), "--json", (dir / "out.json").string()};
        if (std::string(command) == "run") args.insert(args.end(), {"--lcm-log", (dir / "out.lcmlog").string()});
        const Outcome r = run_firtp(args);
        EXPECT_EQ(r.exit_code, 1);
        EXPECT_NE(r.err.find("prog.ngc: line 5: moves Y, an axis the machine does not have"), std::string::npos) << r.err;
        EXPECT_EQ(dir.names(), (std::set<std::string>{"machine.ini", "prog.ngc"}));
    }
}

TEST(BadInput, NegativeFlagValueNamesTheFlag) {
    const Failure f = plan_in_dir(good_program, {"--t1", "-3"});
    EXPECT_EQ(f.outcome.exit_code, 2);
    EXPECT_NE(f.outcome.err.find("--t1"), std::string::npos) << f.outcome.err;
    EXPECT_TRUE(f.left.empty());
}

TEST(BadInput, NonNumericFlagValueNamesTheFlag) {
    const Failure f = plan_in_dir(good_program, {"--period", "fast"});
    EXPECT_EQ(f.outcome.exit_code, 2);
    EXPECT_NE(f.outcome.err.find("--period"), std::string::npos) << f.outcome.err;
    EXPECT_TRUE(f.left.empty());
}

TEST(BadInput, BadToleranceMeaning) {
    const Failure f = plan_in_dir(good_program, {"--tolerance-meaning", "sideways"});
    EXPECT_EQ(f.outcome.exit_code, 2);
    EXPECT_NE(f.outcome.err.find("--tolerance-meaning"), std::string::npos) << f.outcome.err;
    EXPECT_TRUE(f.left.empty());
}

TEST(BadInput, UnknownFlag) {
    const Failure f = plan_in_dir(good_program, {"--fast"});
    EXPECT_EQ(f.outcome.exit_code, 2);
    EXPECT_NE(f.outcome.err.find("--fast"), std::string::npos) << f.outcome.err;
    EXPECT_TRUE(f.left.empty());
}

TEST(BadInput, MissingProgramArgument) {
    const Outcome r = run_firtp({"plan", "--csv", "unused.csv"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("PROGRAM.ngc"), std::string::npos) << r.err;
}

TEST(BadInput, MissingProgramFile) {
    TempDir dir;
    const Outcome r = run_firtp({"plan", (dir / "absent.ngc").string(), "--csv", (dir / "out.csv").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("absent.ngc"), std::string::npos) << r.err;
    EXPECT_TRUE(dir.names().empty());
}

// The second output cannot be written: the first one, already written, is removed again.
TEST(BadInput, UnwritableOutputLeavesNoOtherOutput) {
    TempDir dir;
    write_file(dir / "prog.ngc", good_program);
    const Outcome r = run_firtp({"plan", (dir / "prog.ngc").string(), "--csv", (dir / "out.csv").string(), "--json",
                                 (dir / "missing" / "out.json").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("missing/out.json"), std::string::npos) << r.err;
    EXPECT_EQ(dir.names(), std::set<std::string>{"prog.ngc"});
}

TEST(BadInput, GnuplotMissingNamesThePackage) {
    TempDir empty_path;
    const Failure f = plan_in_dir(good_program, {}, empty_path.path().string());
    EXPECT_EQ(f.outcome.exit_code, 1);
    EXPECT_NE(f.outcome.err.find("gnuplot-nox"), std::string::npos) << f.outcome.err;
    EXPECT_TRUE(f.left.empty());
}

}  // namespace
}  // namespace firtp::cli_test
