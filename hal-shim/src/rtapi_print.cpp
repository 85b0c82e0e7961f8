// rtapi_print.cpp - rtapi_print, rtapi_print_msg, message level and handler, rtapi_snprintf.
#include <atomic>
#include <cerrno>
#include <cstdarg>
#include <cstdio>

#include "rtapi.h"

namespace {

std::atomic<int> g_level{RTAPI_MSG_ERR};

/// Default handler: rtapi_print to stdout, leveled messages to stderr.
void default_handler(msg_level_t level, const char* fmt, va_list ap) {
  std::FILE* out = level == RTAPI_MSG_ALL ? stdout : stderr;
  std::vfprintf(out, fmt, ap);
  std::fflush(out);
}

std::atomic<rtapi_msg_handler_t> g_handler{&default_handler};

}  // namespace

extern "C" {

int rtapi_vsnprintf(char* buf, unsigned long size, const char* fmt, va_list ap) {
  return std::vsnprintf(buf, size, fmt, ap);
}

int rtapi_snprintf(char* buf, unsigned long int size, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  int n = std::vsnprintf(buf, size, fmt, ap);
  va_end(ap);
  return n;
}

void rtapi_print(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  g_handler.load()(RTAPI_MSG_ALL, fmt, ap);
  va_end(ap);
}

void rtapi_print_msg(msg_level_t level, const char* fmt, ...) {
  if (level == RTAPI_MSG_NONE || static_cast<int>(level) > g_level.load()) return;
  va_list ap;
  va_start(ap, fmt);
  g_handler.load()(level, fmt, ap);
  va_end(ap);
}

int rtapi_set_msg_level(int level) {
  if (level < RTAPI_MSG_NONE || level > RTAPI_MSG_ALL) return -EINVAL;
  g_level.store(level);
  return 0;
}

int rtapi_get_msg_level(void) { return g_level.load(); }

void rtapi_set_msg_handler(rtapi_msg_handler_t handler) {
  g_handler.store(handler != nullptr ? handler : &default_handler);
}

rtapi_msg_handler_t rtapi_get_msg_handler(void) { return g_handler.load(); }

}  // extern "C"
