// interpreter_test.cpp - the firtp-hal command language, run in-process on string streams.
#include <sstream>

#include "firtp/hal_shim/interpreter.hpp"
#include "hal_fixture.hpp"

class InterpreterTest : public Hal {
 protected:
  /// Runs 'script' with virtual time; returns the number of errors.
  int run(const std::string& script, hs::InterpreterOptions opt = virtual_time()) {
    out.str("");
    err.str("");
    hs::Interpreter interp(opt, out, err);
    std::istringstream in(script);
    const int errors = interp.run(in, "cfg");
    finished = interp.finished();
    return errors;
  }
  static hs::InterpreterOptions virtual_time() {
    hs::InterpreterOptions o;
    o.realtime = false;
    o.module_dirs = {FIRTP_HAL_TEST_MODULES};
    return o;
  }
  std::ostringstream out, err;
  bool finished = false;
};

TEST(Tokenize, QuotesCommentsAndBlanks) {
  std::vector<std::string> w;
  ASSERT_TRUE(hs::Interpreter::tokenize("  setp a \"b c\"  # comment", w));
  EXPECT_EQ(w, (std::vector<std::string>{"setp", "a", "b c"}));
  ASSERT_TRUE(hs::Interpreter::tokenize("echo a#b \"\"", w));
  EXPECT_EQ(w, (std::vector<std::string>{"echo", "a#b", ""}));
  ASSERT_TRUE(hs::Interpreter::tokenize("# only a comment", w));
  EXPECT_TRUE(w.empty());
  EXPECT_FALSE(hs::Interpreter::tokenize("echo \"open", w));
}

TEST_F(InterpreterTest, ConfigScriptInVirtualTime) {
  const char* script = R"(# a lag chain fed by a counter
loadrt threads name1=servo period1=1000000
loadrt lag count=2
loadrt counter
net pos counter.0.scaled => lag.0.in
net cmd lag.0.out => lag.1.in
setp lag.0.tau 0
lag.1.tau = 0
setp counter.0.enable TRUE
addf counter.0 servo
addf lag.0 servo
addf lag.1 servo
step 8
getp lag.1.out
gets cmd
ptype counter.0.value
stype pos
)";
  EXPECT_EQ(run(script), 0) << err.str();
  EXPECT_EQ(out.str(), "4\n4\ns32\nfloat\n");
}

TEST_F(InterpreterTest, ErrorsNameSourceAndLineAndStopTheScript) {
  EXPECT_EQ(run("loadrt lag\n\nnet x lag.0.in nosuch.pin\necho not reached\n"), 1);
  EXPECT_EQ(err.str(), "cfg:3: pin 'nosuch.pin' not found\n");
  EXPECT_EQ(out.str(), "");
}

TEST_F(InterpreterTest, KeepGoingRunsEveryLineAndCountsErrors) {
  auto opt = virtual_time();
  opt.keep_going = true;
  EXPECT_EQ(run("bogus\nnewsig x\necho reached\nsetp nothing 1\n", opt), 3);
  EXPECT_EQ(out.str(), "reached\n");
  EXPECT_NE(err.str().find("cfg:1: unknown command 'bogus'"), std::string::npos);
  EXPECT_NE(err.str().find("cfg:2: usage: newsig SIGNAL bit|float|s32|u32"), std::string::npos);
  EXPECT_NE(err.str().find("cfg:4: no pin or param named 'nothing'"), std::string::npos);
}

TEST_F(InterpreterTest, ContinuationLinesCountFromTheirFirstLine) {
  EXPECT_EQ(run("loadrt lag \\\n  count=2\nnet x lag.0.out \\\n lag.1.out\n"), 1);
  EXPECT_EQ(err.str(), "cfg:3: signal 'x' would have more than one output pin (lag.1.out)\n");
  EXPECT_TRUE(has_pin("lag.1.in"));
}

TEST_F(InterpreterTest, SleepAndWaitStepVirtualTimeOnceStarted) {
  const char* script = R"(newthread servo 1000000
loadrt counter
addf counter.0 servo
sleep 0.003
getp counter.0.calls
start
sleep 0.005
wait 3
getp counter.0.calls
stop
step 2
getp counter.0.calls
)";
  EXPECT_EQ(run(script), 0) << err.str();
  EXPECT_EQ(out.str(), "0\n8\n10\n");
}

TEST_F(InterpreterTest, StartRunsTheRequestedTicks) {
  auto opt = virtual_time();
  opt.start_ticks = 7;
  EXPECT_EQ(run("newthread t 500000\nloadrt counter\naddf counter.0 t\nstart\ngetp counter.0.calls\n", opt), 0)
      << err.str();
  EXPECT_EQ(out.str(), "7\n");
}

TEST_F(InterpreterTest, RealTimeStartWaitsForTheRequestedTicks) {
  hs::InterpreterOptions opt;
  opt.module_dirs = {FIRTP_HAL_TEST_MODULES};
  opt.start_ticks = 5;
  EXPECT_EQ(run("newthread t 1000000\nloadrt counter\naddf counter.0 t\nstart\nstop\n", opt), 0)
      << err.str();
  EXPECT_GE(value("counter.0.calls"), 5);
}

TEST_F(InterpreterTest, ShowListsWhatIsConfigured) {
  const char* script = R"(loadrt threads name1=servo period1=1000000
loadrt lag
net cmd lag.0.out
addf lag.0 servo
show pin lag.0.o
show sig
show thread
show comp
show funct lag
show param *.tau
)";
  EXPECT_EQ(run(script), 0) << err.str();
  const std::string s = out.str();
  EXPECT_NE(s.find("lag.0.out ==> cmd"), std::string::npos) << s;
  EXPECT_EQ(s.find("lag.0.in "), std::string::npos) << s;
  EXPECT_NE(s.find("<== lag.0.out"), std::string::npos) << s;
  EXPECT_NE(s.find("servo"), std::string::npos) << s;
  EXPECT_NE(s.find("1 lag.0"), std::string::npos) << s;
  EXPECT_NE(s.find("lag.0.tau"), std::string::npos) << s;
  EXPECT_EQ(s.find("lag.0.runs"), std::string::npos) << s;
  EXPECT_EQ(run("show nonsense\n"), 1);
}

TEST_F(InterpreterTest, UsageMessages) {
  auto opt = virtual_time();
  opt.keep_going = true;
  EXPECT_EQ(run("addf\nstep -1\nnewthread t x\nwait abc\nsleep -1\nloadrt\nloadusr halmeter\n", opt), 7);
  const std::string e = err.str();
  EXPECT_NE(e.find("cfg:1: usage: addf FUNCT THREAD [POSITION]"), std::string::npos) << e;
  EXPECT_NE(e.find("cfg:2: usage: step [N]"), std::string::npos) << e;
  EXPECT_NE(e.find("cfg:7: loadusr is not supported"), std::string::npos) << e;
}

TEST_F(InterpreterTest, ExitEndsTheScript) {
  EXPECT_EQ(run("echo one\nexit\necho two\n"), 0);
  EXPECT_EQ(out.str(), "one\n");
  EXPECT_TRUE(finished);
}

TEST_F(InterpreterTest, HelpListsTheCommands) {
  EXPECT_EQ(run("help\n"), 0);
  for (const char* c : {"loadrt", "net", "setp", "addf", "step", "show"})
    EXPECT_NE(out.str().find(c), std::string::npos) << c;
}
