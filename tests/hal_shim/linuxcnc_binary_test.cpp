// linuxcnc_binary_test.cpp - optional: loads LinuxCNC 2.9's own prebuilt lowpass.so into the shim
// (ABI check).  Runs when $FIRTP_LCNC_MODULES (or /usr/lib/linuxcnc/modules) has lowpass.so.
#include <sys/stat.h>

#include <cstdlib>

#include "hal_fixture.hpp"

namespace {

std::string lcnc_modules() {
  const char* env = std::getenv("FIRTP_LCNC_MODULES");
  std::string dir = env != nullptr ? env : "/usr/lib/linuxcnc/modules";
  struct stat st {};
  return ::stat((dir + "/lowpass.so").c_str(), &st) == 0 ? dir : "";
}

}  // namespace

using LinuxCncBinaryTest = Hal;

TEST_F(LinuxCncBinaryTest, RunsLinuxCncLowpassModule) {
  const std::string dir = lcnc_modules();
  if (dir.empty()) GTEST_SKIP() << "no LinuxCNC lowpass.so (set FIRTP_LCNC_MODULES)";
  ASSERT_OK(hs::load_module("lowpass", {"count=1"}, {dir}));
  ASSERT_OK(hs::new_thread("servo", 1000000));
  ASSERT_OK(hs::add_funct("lowpass.0", "servo"));
  ASSERT_OK(hs::set_value("lowpass.0.gain", "0.5"));
  ASSERT_OK(hs::set_value("lowpass.0.in", "2"));
  ASSERT_OK(hs::step(3));
  EXPECT_DOUBLE_EQ(value("lowpass.0.out"), 1.75);
}
