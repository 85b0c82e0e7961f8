// hal_fixture.hpp - a fresh HAL for each test, and helpers to load the test components.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "firtp/hal_shim/runtime.hpp"

namespace hs = firtp::hal_shim;

#define ASSERT_OK(expr)                                \
  do {                                                 \
    const hs::Status st_ = (expr);                     \
    ASSERT_TRUE(st_.ok()) << #expr << ": " << st_.message; \
  } while (0)

#define EXPECT_OK(expr)                                \
  do {                                                 \
    const hs::Status st_ = (expr);                     \
    EXPECT_TRUE(st_.ok()) << #expr << ": " << st_.message; \
  } while (0)

/// Fails unless 'st' failed with a message containing 'text'.
inline ::testing::AssertionResult FailsWith(const hs::Status& st, const std::string& text) {
  if (st.ok()) return ::testing::AssertionFailure() << "succeeded, expected: " << text;
  if (st.message.find(text) == std::string::npos)
    return ::testing::AssertionFailure() << "message '" << st.message << "' lacks '" << text << "'";
  return ::testing::AssertionSuccess();
}

class Hal : public ::testing::Test {
 protected:
  void SetUp() override { hs::reset(); }
  void TearDown() override { hs::reset(); }

  /// loadrt from the test module directory.
  static hs::Status load(const std::string& module, const std::vector<std::string>& args = {}) {
    return hs::load_module(module, args, {FIRTP_HAL_TEST_MODULES});
  }
  /// Value of a pin or param as a double (NaN when missing).
  static double value(const std::string& name) {
    hs::Value v;
    return hs::get_value(name, v).ok() ? v.as_double() : std::nan("");
  }
  /// Value of a signal as a double (NaN when missing).
  static double signal(const std::string& name) {
    hs::Value v;
    return hs::get_signal(name, v).ok() ? v.as_double() : std::nan("");
  }
  static bool has_pin(const std::string& name) {
    for (const auto& p : hs::pins())
      if (p.name == name) return true;
    return false;
  }
};
