// counter.cpp - test component in C++20: a counter that can also feed a hal_stream, written as a
// LinuxCNC 2.9 realtime component would be (only hal.h, rtapi.h, rtapi_app.h).
//
//   loadrt counter [count=N] [step=a,b,...] [key=K]
// per instance i: pins counter.i.enable (bit in), counter.i.value (s32 out),
//                 counter.i.calls (u32 out), counter.i.scaled (float out) = value * scale
//                 param counter.i.scale (float rw, 0.5)
//                 funct counter.i: calls++, if enable: value += step[i]
// key != 0: instance 0 writes {scaled f, enable b, value s, calls u} to stream K every period.
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_AUTHOR("firtp");
MODULE_DESCRIPTION("Counter with a hal_stream writer (hal-shim test component)");
MODULE_LICENSE("GPL");

static int count = 1;
RTAPI_MP_INT(count, "number of counters (1..8)");
static int step[8] = {1, 1, 1, 1, 1, 1, 1, 1};
RTAPI_MP_ARRAY_INT(step, 8, "increment of each counter");
static long key = 0;
RTAPI_MP_LONG(key, "hal_stream key written by counter 0 (0: none)");

namespace {

struct Counter {
  hal_bit_t* enable;
  hal_s32_t* value;
  hal_u32_t* calls;
  hal_float_t* scaled;
  hal_float_t scale;
  int step;
};

int comp_id;
Counter* counters;
hal_stream_t stream;
bool streaming = false;

// One period of counter 'arg'.
void update(void* arg, long) {
  auto* c = static_cast<Counter*>(arg);
  *c->calls = *c->calls + 1;
  if (*c->enable) *c->value = *c->value + c->step;
  *c->scaled = *c->value * c->scale;
  if (streaming && c == &counters[0]) {
    hal_stream_data rec[4];
    rec[0].f = *c->scaled;
    rec[1].b = *c->enable;
    rec[2].s = *c->value;
    rec[3].u = *c->calls;
    hal_stream_write(&stream, rec);
  }
}

// Pins, param and function of counter i.
int export_counter(int i) {
  Counter* c = &counters[i];
  int r = hal_pin_bit_newf(HAL_IN, &c->enable, comp_id, "counter.%d.enable", i);
  if (r == 0) r = hal_pin_s32_newf(HAL_OUT, &c->value, comp_id, "counter.%d.value", i);
  if (r == 0) r = hal_pin_u32_newf(HAL_OUT, &c->calls, comp_id, "counter.%d.calls", i);
  if (r == 0) r = hal_pin_float_newf(HAL_OUT, &c->scaled, comp_id, "counter.%d.scaled", i);
  if (r == 0) r = hal_param_float_newf(HAL_RW, &c->scale, comp_id, "counter.%d.scale", i);
  if (r != 0) return r;
  c->scale = 0.5;
  c->step = step[i];
  char name[HAL_NAME_LEN + 1];  // hal_export_functf is newer than Debian's 2.9 headers
  rtapi_snprintf(name, sizeof name, "counter.%d", i);
  return hal_export_funct(name, update, c, 1, 0, comp_id);
}

}  // namespace

extern "C" int rtapi_app_main(void) {
  if (count < 1 || count > 8) return -EINVAL;
  comp_id = hal_init("counter");
  if (comp_id < 0) return comp_id;
  counters = static_cast<Counter*>(hal_malloc(static_cast<long>(sizeof(Counter)) * count));
  if (counters == nullptr) {
    hal_exit(comp_id);
    return -ENOMEM;
  }
  for (int i = 0; i < count; ++i) {
    if (int r = export_counter(i); r != 0) {
      hal_exit(comp_id);
      return r;
    }
  }
  if (key != 0) {
    if (int r = hal_stream_create(&stream, comp_id, static_cast<int>(key), 64, "fbsu"); r < 0) {
      hal_exit(comp_id);
      return r;
    }
    streaming = true;
  }
  hal_ready(comp_id);
  return 0;
}

extern "C" void rtapi_app_exit(void) {
  if (streaming) hal_stream_destroy(&stream);
  streaming = false;
  hal_exit(comp_id);
}
