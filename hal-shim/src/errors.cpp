// errors.cpp - last-error text per thread, and printing it for C entry points.
#include <cstdarg>

#include "state.hpp"

namespace firtp::hal_shim::detail {

std::string& last_error_text() {
  thread_local std::string text;
  return text;
}

void clear_error() { last_error_text().clear(); }

int fail(int code, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  last_error_text() = vformat(fmt, ap);
  va_end(ap);
  return code;
}

int report(int rc) {
  if (rc < 0) rtapi_print_msg(RTAPI_MSG_ERR, "HAL: ERROR: %s\n", last_error_text().c_str());
  return rc;
}

}  // namespace firtp::hal_shim::detail
