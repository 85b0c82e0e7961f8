// rtapi_time.cpp - rtapi_get_time/clocks (CLOCK_MONOTONIC ns), rtapi_delay, rtapi_clock_set_period.
#include <time.h>

#include <cerrno>

#include "state.hpp"

namespace {

long long now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<long long>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

constexpr long kDelayMax = 10000000;  // 10 ms, enough for hal_stream_wait_*

}  // namespace

extern "C" {

long long int rtapi_get_time(void) { return now_ns(); }

long long int rtapi_get_clocks(void) { return now_ns(); }

long int rtapi_delay_max(void) { return kDelayMax; }

void rtapi_delay(long int nsec) {
  if (nsec <= 0) return;
  if (nsec > kDelayMax) nsec = kDelayMax;
  timespec ts{0, nsec};
  while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
  }
}

long int rtapi_clock_set_period(long int nsecs) {
  using namespace firtp::hal_shim::detail;
  State& s = state();
  Lock lock(s.mu);
  if (nsecs == 0) return s.base_period;
  if (nsecs < 0 || s.base_period != 0) return -EINVAL;
  s.base_period = nsecs;
  return nsecs;
}

}  // extern "C"
