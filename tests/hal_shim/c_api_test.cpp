// c_api_test.cpp - the C API used directly, as a component's rtapi_app_main would: return codes
// and the messages that explain them.
#include <cstdarg>
#include <cstring>
#include <string>

#include "hal.h"
#include "hal_fixture.hpp"
#include "rtapi.h"

namespace {

std::string g_messages;

/// Message handler that collects everything printed.
void collect(msg_level_t, const char* fmt, va_list ap) {
  char buf[512];
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  g_messages += buf;
}

struct Data {
  hal_float_t* x;
  hal_bit_t* b;
  hal_s32_t* s;
  hal_u32_t* u;
  hal_float_t gain;
  hal_s32_t count;
};

void noop(void*, long) {}

}  // namespace

class CApiTest : public Hal {
 protected:
  void SetUp() override {
    Hal::SetUp();
    g_messages.clear();
    rtapi_set_msg_handler(collect);
    id = hal_init("t");
    ASSERT_GT(id, 0);
    d = static_cast<Data*>(hal_malloc(sizeof(Data)));
    ASSERT_NE(d, nullptr);
  }
  void TearDown() override {
    rtapi_set_msg_handler(nullptr);
    Hal::TearDown();
  }
  int id = 0;
  Data* d = nullptr;
};

TEST_F(CApiTest, TypedPinsPointAtWritableDummiesUntilLinked) {
  ASSERT_EQ(hal_pin_float_new("t.x", HAL_IN, &d->x, id), 0);
  ASSERT_EQ(hal_pin_bit_newf(HAL_OUT, &d->b, id, "t.%s", "b"), 0);
  ASSERT_EQ(hal_pin_s32_newf(HAL_IO, &d->s, id, "t.s%d", 1), 0);
  ASSERT_EQ(hal_pin_u32_new("t.u", HAL_OUT, &d->u, id), 0);
  ASSERT_NE(d->x, nullptr);
  EXPECT_EQ(*d->x, 0.0);
  *d->x = 1.5;
  *d->b = true;
  *d->s = -7;
  *d->u = 7;
  EXPECT_EQ(value("t.x"), 1.5);
  EXPECT_EQ(value("t.b"), 1.0);
  EXPECT_EQ(value("t.s1"), -7.0);
  EXPECT_EQ(value("t.u"), 7.0);
  ASSERT_EQ(hal_signal_new("sig", HAL_FLOAT), 0);
  ASSERT_EQ(hal_link("t.x", "sig"), 0);
  ASSERT_OK(hs::set_signal("sig", "9"));
  EXPECT_EQ(*d->x, 9.0);
  ASSERT_EQ(hal_unlink("t.x"), 0);
  EXPECT_EQ(*d->x, 9.0);
}

TEST_F(CApiTest, DuplicatePinNameIsRefusedAndExplained) {
  ASSERT_EQ(hal_pin_float_new("t.x", HAL_IN, &d->x, id), 0);
  EXPECT_EQ(hal_pin_float_new("t.x", HAL_OUT, &d->x, id), -EINVAL);
  EXPECT_NE(hs::last_error().find("duplicate pin name 't.x'"), std::string::npos);
  EXPECT_NE(g_messages.find("HAL: ERROR: duplicate pin name 't.x'"), std::string::npos);
}

TEST_F(CApiTest, NamesLongerThanHalNameLenAreRefused) {
  std::string name(HAL_NAME_LEN + 1, 'n');
  EXPECT_EQ(hal_pin_float_new(name.c_str(), HAL_IN, &d->x, id), -EINVAL);
  EXPECT_NE(hs::last_error().find("too long"), std::string::npos);
  EXPECT_EQ(hal_pin_float_new(name.substr(1).c_str(), HAL_IN, &d->x, id), 0);
  EXPECT_EQ(hal_init(name.c_str()), -EINVAL);
}

TEST_F(CApiTest, PinPointerMustLiveInHalMemory) {
  static hal_float_t* outside = nullptr;
  EXPECT_EQ(hal_pin_float_new("t.x", HAL_IN, &outside, id), -EINVAL);
  EXPECT_NE(hs::last_error().find("not in HAL memory"), std::string::npos);
  static hal_float_t outside_param;
  EXPECT_EQ(hal_param_float_new("t.g", HAL_RW, &outside_param, id), -EINVAL);
}

TEST_F(CApiTest, NothingNewAfterHalReady) {
  ASSERT_EQ(hal_ready(id), 0);
  EXPECT_EQ(hal_ready(id), -EINVAL);
  EXPECT_EQ(hal_pin_float_new("t.x", HAL_IN, &d->x, id), -EINVAL);
  EXPECT_NE(hs::last_error().find("already ready"), std::string::npos);
  EXPECT_EQ(hal_export_funct("t.f", noop, nullptr, 0, 0, id), -EINVAL);
  ASSERT_EQ(hal_set_unready(id), 0);
  EXPECT_EQ(hal_pin_float_new("t.x", HAL_IN, &d->x, id), 0);
}

TEST_F(CApiTest, BadArguments) {
  EXPECT_EQ(hal_init("t"), -EINVAL);  // duplicate component
  EXPECT_EQ(hal_pin_float_new("t.x", static_cast<hal_pin_dir_t>(3), &d->x, id), -EINVAL);
  EXPECT_EQ(hal_pin_new("t.p", HAL_PORT, HAL_IN, static_cast<void**>(static_cast<void*>(&d->x)), id), -EINVAL);
  EXPECT_EQ(hal_pin_float_new("t.x", HAL_IN, &d->x, id + 100), -EINVAL);
  EXPECT_NE(hs::last_error().find("component"), std::string::npos);
  EXPECT_EQ(hal_export_funct("t.f", nullptr, nullptr, 0, 0, id), -EINVAL);
  EXPECT_EQ(hal_exit(id + 100), -EINVAL);
}

TEST_F(CApiTest, ParamsSetByNameWithTypeAndDirectionChecks) {
  ASSERT_EQ(hal_param_float_new("t.gain", HAL_RW, &d->gain, id), 0);
  ASSERT_EQ(hal_param_s32_newf(HAL_RO, &d->count, id, "t.%s", "count"), 0);
  EXPECT_EQ(hal_param_float_set("t.gain", 2.5), 0);
  EXPECT_EQ(d->gain, 2.5);
  EXPECT_EQ(hal_param_s32_set("t.gain", 1), -EINVAL);
  EXPECT_NE(hs::last_error().find("param 't.gain' is float, not s32"), std::string::npos);
  EXPECT_EQ(hal_param_s32_set("t.count", 1), -EINVAL);
  EXPECT_NE(hs::last_error().find("read-only"), std::string::npos);
  EXPECT_EQ(hal_param_float_set("t.nope", 1), -EINVAL);
  double v = 4;
  EXPECT_EQ(hal_param_set("t.gain", HAL_FLOAT, &v), 0);
  EXPECT_EQ(value("t.gain"), 4.0);
  hal_type_t type = HAL_TYPE_UNSPECIFIED;
  hal_data_u* data = nullptr;
  ASSERT_EQ(hal_get_param_value_by_name("t.count", &type, &data), 0);
  EXPECT_EQ(type, HAL_S32);
  EXPECT_EQ(hal_get_param_value_by_name("t.none", &type, &data), -1);
}

TEST_F(CApiTest, ExportFunctfNamesTheFunctionAndItsTimeParams) {
  ASSERT_EQ(hal_export_functf(noop, nullptr, 1, 0, id, "t.f%d", 3), 0);
  auto f = hs::functs();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].name, "t.f3");
  EXPECT_EQ(f[0].owner, "t");
  EXPECT_EQ(value("t.f3.time"), 0.0);
  EXPECT_EQ(value("t.f3.tmax"), 0.0);
  EXPECT_EQ(hal_export_funct("t.f3", noop, nullptr, 1, 0, id), -EINVAL);
  EXPECT_NE(hs::last_error().find("duplicate function name 't.f3'"), std::string::npos);
}

TEST_F(CApiTest, HalExitRemovesEverythingTheComponentMade) {
  ASSERT_EQ(hal_pin_float_new("t.x", HAL_OUT, &d->x, id), 0);
  ASSERT_EQ(hal_param_float_new("t.gain", HAL_RW, &d->gain, id), 0);
  ASSERT_EQ(hal_export_funct("t.f", noop, nullptr, 1, 0, id), 0);
  ASSERT_OK(hs::net("s", {"t.x"}));
  EXPECT_STREQ(hal_comp_name(id), "t");
  ASSERT_EQ(hal_exit(id), 0);
  EXPECT_EQ(hal_comp_name(id), nullptr);
  EXPECT_TRUE(hs::pins().empty());
  EXPECT_TRUE(hs::params().empty());
  EXPECT_TRUE(hs::functs().empty());
  EXPECT_TRUE(hs::signals().at(0).writer.empty());
  id = hal_init("t");  // the name is free again
  EXPECT_GT(id, 0);
}

TEST_F(CApiTest, HalMallocIsAlignedZeroedAndBounded) {
  for (long size : {1L, 3L, 8L, 100L}) {
    auto* p = static_cast<unsigned char*>(hal_malloc(size));
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % 16, 0u);
    for (long i = 0; i < size; ++i) EXPECT_EQ(p[i], 0);
  }
  const std::size_t before = hs::arena_used();
  EXPECT_EQ(hal_malloc(static_cast<long>(hs::arena_size())), nullptr);
  EXPECT_NE(g_messages.find("HAL memory full"), std::string::npos);
  EXPECT_EQ(hs::arena_used(), before);
  EXPECT_EQ(hal_malloc(0), nullptr);
}

TEST_F(CApiTest, RtapiUtilities) {
  char buf[8];
  EXPECT_EQ(rtapi_snprintf(buf, sizeof buf, "%d-%s", 12, "abcdefgh"), 11);
  EXPECT_STREQ(buf, "12-abcd");
  const long long t0 = rtapi_get_time();
  rtapi_delay(1000000);
  EXPECT_GE(rtapi_get_time() - t0, 1000000);
  EXPECT_GE(rtapi_get_clocks(), t0);
  EXPECT_EQ(rtapi_set_msg_level(RTAPI_MSG_ALL + 1), -EINVAL);
  const int old = rtapi_get_msg_level();
  ASSERT_EQ(rtapi_set_msg_level(RTAPI_MSG_NONE), 0);
  rtapi_print_msg(RTAPI_MSG_ERR, "hidden\n");
  rtapi_print("shown %d\n", 1);
  ASSERT_EQ(rtapi_set_msg_level(old), 0);
  EXPECT_EQ(g_messages, "shown 1\n");
  EXPECT_EQ(rtapi_is_kernelspace(), 0);
}

TEST_F(CApiTest, SharedMemoryIsFoundByKey) {
  const int a = rtapi_shmem_new(77, id, 100);
  ASSERT_GT(a, 0);
  const int b = rtapi_shmem_new(77, id, 50);
  EXPECT_EQ(a, b);
  void* pa = nullptr;
  ASSERT_EQ(rtapi_shmem_getptr(a, &pa), 0);
  EXPECT_EQ(static_cast<unsigned char*>(pa)[99], 0);
  EXPECT_EQ(rtapi_shmem_new(77, id, 1000), -EINVAL);  // bigger than the block
  EXPECT_EQ(rtapi_shmem_delete(a, id), 0);
  EXPECT_EQ(rtapi_shmem_delete(b, id), 0);
  EXPECT_EQ(rtapi_shmem_getptr(a, &pa), -EINVAL);  // freed with its last user
}
