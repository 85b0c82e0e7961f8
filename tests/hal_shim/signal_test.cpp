// signal_test.cpp - signals and links: pointers repointed like real HAL, halcmd rules and errors.
#include "hal.h"
#include "hal_fixture.hpp"

class SignalTest : public Hal {
 protected:
  void SetUp() override {
    Hal::SetUp();
    ASSERT_OK(load("lag", {"count=2"}));
    ASSERT_OK(load("counter"));
    ASSERT_OK(hs::new_thread("servo", 1000000));
  }
  /// Address a pin currently points at.
  static void* target(const char* pin) {
    hal_data_u* d = nullptr;
    EXPECT_EQ(hal_get_pin_value_by_name(pin, nullptr, &d, nullptr), 0) << pin;
    return const_cast<hal_data_u*>(d);
  }
};

TEST_F(SignalTest, NetPointsEveryPinAtTheSignalStorage) {
  ASSERT_OK(hs::net("cmd", {"lag.0.out", "=>", "lag.1.in"}));
  hal_data_u* sig = nullptr;
  bool has_writer = false;
  ASSERT_EQ(hal_get_signal_value_by_name("cmd", nullptr, &sig, &has_writer), 0);
  EXPECT_TRUE(has_writer);
  EXPECT_EQ(target("lag.0.out"), sig);
  EXPECT_EQ(target("lag.1.in"), sig);
  auto sigs = hs::signals();
  ASSERT_EQ(sigs.size(), 1u);
  EXPECT_EQ(sigs[0].type, hs::Type::Float);
  EXPECT_EQ(sigs[0].writer, "lag.0.out");
  EXPECT_EQ(sigs[0].readers, std::vector<std::string>{"lag.1.in"});
}

TEST_F(SignalTest, ValuesFlowFromOneComponentToAnother) {
  ASSERT_OK(hs::net("pos", {"counter.0.scaled", "lag.0.in"}));
  ASSERT_OK(hs::set_value("lag.0.tau", "0"));
  ASSERT_OK(hs::set_value("counter.0.enable", "1"));
  ASSERT_OK(hs::add_funct("counter.0", "servo"));
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::step(6));
  EXPECT_EQ(value("counter.0.value"), 6);
  EXPECT_EQ(signal("pos"), 3.0);
  EXPECT_EQ(value("lag.0.out"), 3.0);
}

TEST_F(SignalTest, FirstLinkedPinSeedsTheSignal) {
  ASSERT_OK(hs::set_value("lag.0.in", "3.25"));
  ASSERT_OK(hs::net("x", {"lag.0.in"}));
  EXPECT_EQ(signal("x"), 3.25);
}

TEST_F(SignalTest, SetsReachesTheComponent) {
  ASSERT_OK(hs::net("x", {"lag.0.in"}));
  ASSERT_OK(hs::set_signal("x", "2"));
  ASSERT_OK(hs::set_value("lag.0.tau", "0"));
  ASSERT_OK(hs::add_funct("lag.0", "servo"));
  ASSERT_OK(hs::step(1));
  EXPECT_EQ(value("lag.0.out"), 2.0);
  EXPECT_EQ(value("lag.0.in"), 2.0);  // getp on a linked pin reads the signal
}

TEST_F(SignalTest, UnlinkedPinKeepsTheSignalsLastValue) {
  ASSERT_OK(hs::net("x", {"lag.0.in"}));
  ASSERT_OK(hs::set_signal("x", "4"));
  void* linked = target("lag.0.in");
  ASSERT_OK(hs::unlink("lag.0.in"));
  EXPECT_NE(target("lag.0.in"), linked);
  EXPECT_EQ(value("lag.0.in"), 4.0);
  ASSERT_OK(hs::set_value("lag.0.in", "5"));  // writable again once unlinked
  EXPECT_EQ(signal("x"), 4.0);
}

TEST_F(SignalTest, DeletingASignalUnlinksItsPins) {
  ASSERT_OK(hs::net("x", {"lag.0.out", "lag.1.in"}));
  ASSERT_OK(hs::delete_signal("x"));
  for (const auto& p : hs::pins()) EXPECT_TRUE(p.signal.empty()) << p.name;
  EXPECT_TRUE(FailsWith(hs::delete_signal("x"), "signal 'x' not found"));
}

TEST_F(SignalTest, LinkpsAndRelinkToSameSignal) {
  ASSERT_OK(hs::new_signal("y", hs::Type::Bit));
  ASSERT_OK(hs::link("counter.0.enable", "y"));
  ASSERT_OK(hs::link("counter.0.enable", "y"));  // already there: fine
  ASSERT_OK(hs::net("y", {"counter.0.enable"}));
  ASSERT_OK(hs::set_signal("y", "TRUE"));
  EXPECT_EQ(value("counter.0.enable"), 1.0);
}

TEST_F(SignalTest, NamesThatDoNotExist) {
  EXPECT_TRUE(FailsWith(hs::net("x", {"lag.0.inn"}), "pin 'lag.0.inn' not found"));
  EXPECT_TRUE(FailsWith(hs::link("lag.0.in", "nosig"), "signal 'nosig' not found"));
  EXPECT_TRUE(FailsWith(hs::set_value("lag.9.in", "1"), "no pin or param named 'lag.9.in'"));
  EXPECT_TRUE(FailsWith(hs::set_signal("nosig", "1"), "signal 'nosig' not found"));
  EXPECT_TRUE(FailsWith(hs::unlink("nopin"), "pin 'nopin' not found"));
}

TEST_F(SignalTest, DuplicateSignalName) {
  ASSERT_OK(hs::new_signal("a", hs::Type::Float));
  EXPECT_TRUE(FailsWith(hs::new_signal("a", hs::Type::S32), "duplicate signal name 'a'"));
}

TEST_F(SignalTest, TypeMismatch) {
  EXPECT_TRUE(FailsWith(hs::net("v", {"counter.0.value", "lag.0.in"}),
                        "type mismatch: pin 'lag.0.in' is float but signal 'v' is s32"));
  ASSERT_OK(hs::new_signal("b", hs::Type::Bit));
  EXPECT_TRUE(FailsWith(hs::link("lag.0.in", "b"), "type mismatch"));
}

TEST_F(SignalTest, OneWriterPerSignal) {
  EXPECT_TRUE(FailsWith(hs::net("x", {"lag.0.out", "lag.1.out"}), "more than one output pin"));
  ASSERT_OK(hs::net("x", {"lag.0.out"}));
  EXPECT_TRUE(FailsWith(hs::net("x", {"lag.1.out"}), "more than one output pin"));
  EXPECT_TRUE(FailsWith(hs::link("lag.1.out", "x"), "already has output pin 'lag.0.out'"));
}

TEST_F(SignalTest, PinLinkedElsewhere) {
  ASSERT_OK(hs::net("a", {"lag.0.in"}));
  EXPECT_TRUE(FailsWith(hs::net("b", {"lag.0.in"}), "already linked to signal 'a'"));
}

TEST_F(SignalTest, NetIsAllOrNothing) {
  EXPECT_FALSE(hs::net("s", {"lag.0.in", "nosuch"}).ok());
  EXPECT_TRUE(hs::signals().empty());
  EXPECT_TRUE(FailsWith(hs::net("lag.0.out", {"lag.1.in"}), "also the name of a pin"));
  EXPECT_TRUE(FailsWith(hs::net("s", {"=>"}), "no pins given"));
}

TEST_F(SignalTest, WhatSetpAndSetsRefuse) {
  ASSERT_OK(hs::net("x", {"lag.0.out", "lag.1.in"}));
  EXPECT_TRUE(FailsWith(hs::set_value("lag.1.in", "1"), "linked to signal 'x': use sets x"));
  EXPECT_TRUE(FailsWith(hs::set_value("lag.1.out", "1"), "is an output"));
  EXPECT_TRUE(FailsWith(hs::set_signal("x", "1"), "written by pin 'lag.0.out'"));
  EXPECT_TRUE(FailsWith(hs::set_value("lag.0.runs", "1"), "param 'lag.0.runs' is read-only"));
}

TEST_F(SignalTest, ValuesMustParseAsTheTargetType) {
  EXPECT_TRUE(FailsWith(hs::set_value("lag.0.in", "abc"), "'abc' is not a float"));
  EXPECT_TRUE(FailsWith(hs::set_value("counter.0.enable", "2"), "'2' is not a bit"));
  EXPECT_TRUE(FailsWith(hs::set_value("servo.tmax", "3000000000"), "is not an s32"));
  ASSERT_OK(hs::new_signal("u", hs::Type::U32));
  EXPECT_TRUE(FailsWith(hs::set_signal("u", "-1"), "is not a u32"));
  ASSERT_OK(hs::set_signal("u", "0xffffffff"));
  EXPECT_EQ(signal("u"), 4294967295.0);
}

TEST(ValueText, ParsesAndFormatsEveryType) {
  hs::Value v;
  ASSERT_OK(hs::parse_value(hs::Type::Bit, "true", v));
  EXPECT_EQ(hs::format_value(v), "TRUE");
  ASSERT_OK(hs::parse_value(hs::Type::Bit, "0", v));
  EXPECT_EQ(hs::format_value(v), "FALSE");
  ASSERT_OK(hs::parse_value(hs::Type::Float, "0.1", v));
  EXPECT_EQ(hs::format_value(v), "0.1");
  ASSERT_OK(hs::parse_value(hs::Type::Float, "-1e-300", v));
  EXPECT_EQ(hs::format_value(v), "-1e-300");
  ASSERT_OK(hs::parse_value(hs::Type::S32, "-2147483648", v));
  EXPECT_EQ(hs::format_value(v), "-2147483648");
  EXPECT_FALSE(hs::parse_value(hs::Type::S32, "2147483648", v).ok());
  ASSERT_OK(hs::parse_value(hs::Type::U32, "0x10", v));
  EXPECT_EQ(hs::format_value(v), "16");
  EXPECT_FALSE(hs::parse_value(hs::Type::U32, "", v).ok());
  hs::Type t;
  EXPECT_TRUE(hs::parse_type("FLOAT", t));
  EXPECT_EQ(t, hs::Type::Float);
  EXPECT_FALSE(hs::parse_type("double", t));
}
