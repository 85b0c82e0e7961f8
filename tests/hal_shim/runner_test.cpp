// runner_test.cpp - the firtp-hal binary: files, stdin, options, exit status, error lines.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {

struct Result {
  int status;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class RunnerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/firtp-hal-test-XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    dir = tmpl;
  }
  void TearDown() override { std::system(("rm -rf '" + dir + "'").c_str()); }

  /// Writes 'script' to DIR/cfg.hal and runs "firtp-hal -L MODULES ARGS" in DIR.
  Result run(const std::string& args, const std::string& script = "") {
    std::ofstream(dir + "/cfg.hal") << script;
    const std::string cmd = "cd '" + dir + "' && '" FIRTP_HAL_BIN "' -L '" FIRTP_HAL_TEST_MODULES
                            "' " + args + " >out.txt 2>err.txt";
    const int rc = std::system(cmd.c_str());
    return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(dir + "/out.txt"), slurp(dir + "/err.txt")};
  }
  std::string dir;
};

const char* const kCounterScript = R"(loadrt threads name1=servo period1=1000000
loadrt counter
setp counter.0.enable 1
addf counter.0 servo
start
stop
getp counter.0.value
)";

}  // namespace

TEST_F(RunnerTest, RunsAFileForFixedTicksWithoutTheClock) {
  Result r = run("--no-realtime -n 100 -f cfg.hal", kCounterScript);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "100\n");
  EXPECT_EQ(r.err, "");
}

TEST_F(RunnerTest, FileMayBeGivenWithoutDashF) {
  Result r = run("--no-realtime -n 3 cfg.hal", kCounterScript);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "3\n");
}

TEST_F(RunnerTest, ReadsStandardInput) {
  Result r = run("--no-realtime -n 5 < cfg.hal", kCounterScript);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "5\n");
}

TEST_F(RunnerTest, ErrorsPrintFileAndLineAndExitNonZero) {
  Result r = run("--no-realtime -f cfg.hal", "loadrt counter\n# comment\nnet x counter.0.value\nsetp x 1\necho no\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cfg.hal:4: no pin or param named 'x'\n");
  EXPECT_EQ(r.out, "");
  r = run("--no-realtime < cfg.hal", "newsig a float\nnewsig a float\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "<stdin>:2: duplicate signal name 'a'\n");
}

TEST_F(RunnerTest, KeepGoingStillFails) {
  Result r = run("-k --no-realtime -f cfg.hal", "bogus\necho after\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "after\n");
}

TEST_F(RunnerTest, RealClockRunsThreads) {
  Result r = run("-f cfg.hal", R"(newthread servo 1000000
loadrt counter
addf counter.0 servo
start
sleep 0.1
stop
show thread
)");
  EXPECT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  long cycles = -1;
  while (std::getline(lines, line))
    if (line.find("servo") != std::string::npos) {
      std::istringstream f(line);
      std::string period, fp;
      f >> period >> fp >> cycles;
    }
  EXPECT_GT(cycles, 10) << r.out;
  EXPECT_LE(cycles, 110) << r.out;
}

TEST_F(RunnerTest, RealClockStartWaitsForTicks) {
  Result r = run("-n 20 -f cfg.hal", kCounterScript);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_GE(std::atoi(r.out.c_str()), 20) << r.out;
}

TEST_F(RunnerTest, OptionErrorsAndHelp) {
  EXPECT_EQ(run("-f no-such-file.hal").status, 2);
  EXPECT_EQ(run("--bogus").status, 2);
  EXPECT_EQ(run("-n").status, 2);
  Result r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--no-realtime"), std::string::npos);
}

TEST_F(RunnerTest, ComponentMessagesReachStderr) {
  Result r = run("--no-realtime -f cfg.hal", "loadrt lag count=12\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("lag: count=12 is not in 1..8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cfg.hal:1: loadrt lag: rtapi_app_main failed: Invalid argument"),
            std::string::npos)
      << r.err;
}
