// load_test.cpp - loadrt/unloadrt of the test components: module parameters, errors, cleanup.
#include <cmath>

#include "hal_fixture.hpp"

using LoadTest = Hal;

TEST_F(LoadTest, LoadsComponentWithPinsParamsAndFunctions) {
  ASSERT_OK(load("lag", {"count=2"}));
  EXPECT_EQ(hs::loaded_modules(), std::vector<std::string>{"lag"});
  auto comps = hs::components();
  ASSERT_EQ(comps.size(), 1u);
  EXPECT_EQ(comps[0].name, "lag");
  EXPECT_EQ(comps[0].module, "lag");
  EXPECT_TRUE(comps[0].ready);
  for (const char* pin : {"lag.0.in", "lag.0.out", "lag.0.reset", "lag.1.in", "lag.1.out"})
    EXPECT_TRUE(has_pin(pin)) << pin;
  EXPECT_DOUBLE_EQ(value("lag.1.tau"), 0.01);
  std::vector<std::string> names;
  for (const auto& f : hs::functs()) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"lag.0", "lag.1"}));
  for (const auto& p : hs::pins())
    if (p.name == "lag.0.out") {
      EXPECT_EQ(p.type, hs::Type::Float);
      EXPECT_EQ(p.dir, hs::PinDir::Out);
      EXPECT_EQ(p.owner, "lag");
    }
}

TEST_F(LoadTest, SetsIntStringArrayModuleParameters) {
  ASSERT_OK(load("lag", {"count=3", "prefix=lp"}));
  EXPECT_TRUE(has_pin("lp.2.out"));
  EXPECT_FALSE(has_pin("lag.0.out"));
  ASSERT_OK(load("counter", {"count=2", "step=3,5"}));
  ASSERT_OK(hs::new_thread("t", 1000000));
  ASSERT_OK(hs::add_funct("counter.0", "t"));
  ASSERT_OK(hs::add_funct("counter.1", "t"));
  ASSERT_OK(hs::set_value("counter.0.enable", "1"));
  ASSERT_OK(hs::set_value("counter.1.enable", "TRUE"));
  ASSERT_OK(hs::step(4));
  EXPECT_EQ(value("counter.0.value"), 12);
  EXPECT_EQ(value("counter.1.value"), 20);
}

TEST_F(LoadTest, QuotedStringParameterLosesItsQuotes) {
  ASSERT_OK(load("lag", {"prefix=\"q\""}));
  EXPECT_TRUE(has_pin("q.0.in"));
}

TEST_F(LoadTest, UnknownModuleParameterIsRefused) {
  EXPECT_TRUE(FailsWith(load("lag", {"cuont=2"}), "unknown parameter 'cuont'"));
  EXPECT_TRUE(hs::loaded_modules().empty());
  EXPECT_TRUE(hs::components().empty());
}

TEST_F(LoadTest, BadParameterValuesAreRefused) {
  EXPECT_TRUE(FailsWith(load("lag", {"count=two"}), "count='two' is not an int"));
  EXPECT_TRUE(FailsWith(load("lag", {"count"}), "'count' is not name=value"));
  EXPECT_TRUE(FailsWith(load("counter", {"step=1,2,3,4,5,6,7,8,9"}), "at most 8 values"));
  EXPECT_TRUE(FailsWith(load("counter", {"key=x"}), "is not a long"));
  EXPECT_TRUE(hs::loaded_modules().empty());
}

TEST_F(LoadTest, FailingRtapiAppMainLeavesNothingBehind) {
  EXPECT_TRUE(FailsWith(load("lag", {"count=9"}), "rtapi_app_main failed"));
  EXPECT_TRUE(hs::loaded_modules().empty());
  EXPECT_TRUE(hs::components().empty());
  EXPECT_TRUE(hs::pins().empty());
}

TEST_F(LoadTest, MissingModuleSaysWhereItLooked) {
  hs::Status st = load("nosuch");
  EXPECT_TRUE(FailsWith(st, "nosuch.so not found"));
  EXPECT_TRUE(FailsWith(st, FIRTP_HAL_TEST_MODULES));
  EXPECT_TRUE(FailsWith(hs::load_module("/no/such/dir/x.so", {}), "no such file"));
}

TEST_F(LoadTest, LoadsByPath) {
  ASSERT_OK(hs::load_module(std::string(FIRTP_HAL_TEST_MODULES) + "/lag.so", {}));
  EXPECT_TRUE(has_pin("lag.0.in"));
}

TEST_F(LoadTest, SecondLoadOfAModuleIsRefused) {
  ASSERT_OK(load("lag"));
  EXPECT_TRUE(FailsWith(load("lag"), "module 'lag' is already loaded"));
}

TEST_F(LoadTest, DuplicateComponentNameFailsTheLoad) {
  ASSERT_OK(load("lag", {"prefix=counter"}));
  EXPECT_TRUE(FailsWith(load("counter"), "duplicate component name 'counter'"));
  EXPECT_EQ(hs::loaded_modules(), std::vector<std::string>{"lag"});
}

TEST_F(LoadTest, UnloadRemovesPinsFunctionsAndThreadEntries) {
  ASSERT_OK(load("lag"));
  ASSERT_OK(hs::new_thread("servo", 1000000));
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::set_value("lag.0.in", "2"));
  ASSERT_OK(hs::set_value("lag.0.tau", "0"));
  ASSERT_OK(hs::net("out", {"lag.0.out"}));
  ASSERT_OK(hs::step(1));
  ASSERT_OK(hs::unload_module("lag"));
  EXPECT_TRUE(hs::pins().empty());
  EXPECT_TRUE(hs::functs().empty());
  EXPECT_TRUE(hs::threads().at(0).functs.empty());
  EXPECT_EQ(signal("out"), 2.0);  // signals outlive their pins
  ASSERT_OK(hs::step(3));         // the thread still runs, now with nothing to call
  EXPECT_TRUE(FailsWith(hs::unload_module("lag"), "module 'lag' is not loaded"));
}

TEST_F(LoadTest, ReloadStartsFromFreshModuleState) {
  ASSERT_OK(load("lag", {"count=2"}));
  ASSERT_OK(hs::unload_module("lag"));
  ASSERT_OK(load("lag"));
  EXPECT_TRUE(has_pin("lag.0.in"));
  EXPECT_FALSE(has_pin("lag.1.in"));
}

TEST_F(LoadTest, BuiltInThreadsModule) {
  ASSERT_OK(hs::load_module("threads", {"name1=fast", "period1=250000", "name2=slow",
                                        "period2=1000000", "fp2=0"}));
  auto t = hs::threads();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "fast");
  EXPECT_EQ(t[0].period_ns, 250000);
  EXPECT_EQ(t[1].period_ns, 1000000);
  EXPECT_FALSE(t[1].uses_fp);
  EXPECT_EQ(hs::base_period_ns(), 250000);
  ASSERT_OK(hs::unload_module("threads"));
  EXPECT_TRUE(hs::threads().empty());
  EXPECT_TRUE(FailsWith(hs::load_module("threads", {"name1=x", "period1=0"}), "period1='0'"));
  EXPECT_TRUE(FailsWith(hs::load_module("threads", {"nmae1=x"}), "unknown argument 'nmae1=x'"));
}
