// thread_test.cpp - threads: deterministic stepping, call order, multi-rate, real clock, errors.
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "hal.h"
#include "hal_fixture.hpp"

namespace {

int g_log[16];
int g_log_len = 0;

/// Appends its argument (an int id) to the call log.
void log_call(void* arg, long) {
  if (g_log_len < 16) g_log[g_log_len++] = static_cast<int>(reinterpret_cast<std::intptr_t>(arg));
}

void* tag(int n) { return reinterpret_cast<void*>(static_cast<std::intptr_t>(n)); }

}  // namespace

class ThreadTest : public Hal {
 protected:
  void SetUp() override {
    Hal::SetUp();
    g_log_len = 0;
    ASSERT_OK(load("lag"));
    ASSERT_OK(hs::new_thread("servo", 1000000));
  }
  /// Exports f1..f3 (log_call with ids 1..3) from an in-process component "fn".
  static void export_logging_functs(int reentrant = 0, int uses_fp = 0) {
    const int id = hal_init("fn");
    ASSERT_GT(id, 0);
    for (int i = 1; i <= 3; ++i)
      ASSERT_EQ(hal_export_functf(log_call, tag(i), uses_fp, reentrant, id, "f%d", i), 0);
    ASSERT_EQ(hal_ready(id), 0);
  }
  static std::vector<int> log() { return {g_log, g_log + g_log_len}; }
};

TEST_F(ThreadTest, StepRunsTheFunctionOncePerPeriod) {
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::set_value("lag.0.in", "1"));
  ASSERT_OK(hs::step(100));
  const double a = std::exp(-0.001 / 0.01);
  double expected = 0;
  for (int i = 0; i < 100; ++i) expected += (1.0 - expected) * (1.0 - a);
  EXPECT_NEAR(value("lag.0.out"), expected, 1e-15);
  EXPECT_NEAR(expected, 1.0 - std::pow(a, 100), 1e-12);
  EXPECT_EQ(value("lag.0.runs"), 100);
  EXPECT_EQ(hs::thread_cycles("servo"), 100u);
  EXPECT_GE(value("lag.0.tmax"), value("lag.0.time"));
  EXPECT_GE(value("servo.tmax"), 0.0);
}

TEST_F(ThreadTest, ResetPinAndPassThrough) {
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::set_value("lag.0.in", "2"));
  ASSERT_OK(hs::set_value("lag.0.tau", "0"));
  ASSERT_OK(hs::step(1));
  EXPECT_EQ(value("lag.0.out"), 2.0);
  ASSERT_OK(hs::set_value("lag.0.reset", "1"));
  ASSERT_OK(hs::step(1));
  EXPECT_EQ(value("lag.0.out"), 0.0);
}

TEST_F(ThreadTest, FunctionsRunInAddfOrder) {
  export_logging_functs();
  ASSERT_OK(hs::add_funct("f2", "servo"));
  ASSERT_OK(hs::add_funct("f1", "servo", 1));
  ASSERT_OK(hs::add_funct("f3", "servo", -1));
  EXPECT_EQ(hs::threads().at(0).functs, (std::vector<std::string>{"f1", "f2", "f3"}));
  ASSERT_OK(hs::step(2));
  EXPECT_EQ(log(), (std::vector<int>{1, 2, 3, 1, 2, 3}));
  ASSERT_OK(hs::del_funct("f2", "servo"));
  g_log_len = 0;
  ASSERT_OK(hs::step(1));
  EXPECT_EQ(log(), (std::vector<int>{1, 3}));
  for (const auto& f : hs::functs())
    if (f.name == "f2") {
      EXPECT_EQ(f.users, 0);
    }
}

TEST_F(ThreadTest, ReentrantFunctionMayRunInTwoThreads) {
  export_logging_functs(1);
  ASSERT_OK(hs::new_thread("slow", 2000000));
  ASSERT_OK(hs::add_funct("f1", "servo"));
  ASSERT_OK(hs::add_funct("f1", "slow"));
  ASSERT_OK(hs::step(2));
  EXPECT_EQ(log(), (std::vector<int>{1, 1, 1}));
}

TEST_F(ThreadTest, ThreadsRunAtMultiplesOfTheBasePeriod) {
  ASSERT_OK(load("counter"));
  ASSERT_OK(hs::new_thread("slow", 2600000));  // rounded to 3 ms
  EXPECT_EQ(hs::threads().at(1).period_ns, 3000000);
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::add_funct("counter.0", "slow"));
  ASSERT_OK(hs::step(9));
  EXPECT_EQ(hs::thread_cycles("servo"), 9u);
  EXPECT_EQ(hs::thread_cycles("slow"), 3u);
  EXPECT_EQ(value("counter.0.calls"), 3);
  EXPECT_TRUE(FailsWith(hs::new_thread("fast", 500000), "shorter than the base period"));
  EXPECT_TRUE(FailsWith(hs::new_thread("servo", 1000000), "duplicate thread name"));
}

TEST_F(ThreadTest, AddfErrorsSayWhy) {
  export_logging_functs();
  ASSERT_OK(hs::new_thread("nofp", 1000000, false));
  EXPECT_TRUE(FailsWith(hs::add_funct("nosuch", "servo"), "function 'nosuch' not found"));
  EXPECT_TRUE(FailsWith(hs::add_funct("f1", "nosuch"), "thread 'nosuch' not found"));
  EXPECT_TRUE(FailsWith(hs::add_funct("f1", "servo", 0), "position 0"));
  EXPECT_TRUE(FailsWith(hs::add_funct("f1", "servo", 3), "out of range"));
  EXPECT_TRUE(FailsWith(hs::add_funct("lag.0", "nofp"), "uses floating point"));
  ASSERT_OK(hs::add_funct("f1", "servo"));
  EXPECT_TRUE(FailsWith(hs::add_funct("f1", "nofp"), "not reentrant"));
  EXPECT_TRUE(FailsWith(hs::del_funct("f2", "servo"), "function 'f2' is not in thread 'servo'"));
}

TEST_F(ThreadTest, StepNeedsAThreadAndStoppedThreads) {
  ASSERT_OK(hs::delete_thread("servo"));
  EXPECT_TRUE(FailsWith(hs::step(1), "no thread to step"));
  EXPECT_EQ(hs::base_period_ns(), 0);
  ASSERT_OK(hs::new_thread("servo", 1000000));
  ASSERT_OK(hs::start_threads());
  EXPECT_TRUE(FailsWith(hs::step(1), "'stop' before stepping"));
  EXPECT_TRUE(FailsWith(hs::delete_thread("servo"), "stop threads"));
  ASSERT_OK(hs::stop_threads());
}

TEST_F(ThreadTest, RealClockRunsFunctionsEveryPeriod) {
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::set_value("lag.0.in", "1"));
  ASSERT_OK(hs::start_threads());
  EXPECT_TRUE(hs::threads_running());
  std::this_thread::sleep_for(std::chrono::milliseconds(120));
  ASSERT_OK(hs::stop_threads());
  EXPECT_FALSE(hs::threads_running());
  const auto cycles = hs::thread_cycles("servo");
  EXPECT_GE(cycles, 20u);   // 120 periods ideally; generous for a loaded CI machine
  EXPECT_LE(cycles, 130u);  // and never faster than the clock
  EXPECT_EQ(value("lag.0.runs"), static_cast<double>(cycles));
  EXPECT_GT(value("lag.0.out"), 0.5);
  EXPECT_GT(value("servo.tmax"), 0.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(hs::thread_cycles("servo"), cycles);  // stopped means stopped
}

TEST_F(ThreadTest, UnloadWhileRunningTakesTheFunctionOutFirst) {
  ASSERT_OK(load("counter"));
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::add_funct("counter.0", "servo"));
  ASSERT_OK(hs::start_threads());
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_OK(hs::unload_module("lag"));
  const auto before = hs::thread_cycles("servo");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_GT(hs::thread_cycles("servo"), before);
  EXPECT_EQ(hs::threads().at(0).functs, std::vector<std::string>{"counter.0"});
  ASSERT_OK(hs::stop_threads());
}

TEST_F(ThreadTest, AddfWhileRunningIsPickedUp) {
  ASSERT_OK(hs::start_threads());
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  // lag.0.tmax is written by the thread (atomically) once lag.0 has run.
  const auto start = std::chrono::steady_clock::now();
  while (value("lag.0.tmax") <= 0 && std::chrono::steady_clock::now() - start < std::chrono::seconds(5))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_OK(hs::stop_threads());
  EXPECT_GE(value("lag.0.runs"), 1);
}

TEST_F(ThreadTest, CApiCreatesAndStartsThreads) {
  EXPECT_GT(hal_create_thread("aux", 2000000, 1), 0);
  EXPECT_EQ(hal_add_funct_to_thread("lag.0", "aux", -1), 0);
  EXPECT_EQ(hal_add_funct_to_thread("lag.0", "servo", -1), -EINVAL);  // not reentrant
  EXPECT_EQ(hal_start_threads(), 0);
  EXPECT_EQ(hal_stop_threads(), 0);
  EXPECT_EQ(hal_del_funct_from_thread("lag.0", "aux"), 0);
  EXPECT_EQ(hal_thread_delete("aux"), 0);
  EXPECT_EQ(hal_thread_delete("aux"), -EINVAL);
}
