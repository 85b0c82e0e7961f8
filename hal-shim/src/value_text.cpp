// value_text.cpp - HAL values to and from text (halcmd conventions).
#include <cerrno>
#include <charconv>
#include <cinttypes>
#include <climits>
#include <cstdlib>
#include <strings.h>

#include "firtp/hal_shim/runtime.hpp"

namespace firtp::hal_shim {

double Value::as_double() const {
  switch (type) {
    case Type::Bit: return b ? 1.0 : 0.0;
    case Type::S32: return s;
    case Type::U32: return u;
    default: return f;
  }
}

const char* type_name(Type type) {
  switch (type) {
    case Type::Bit: return "bit";
    case Type::Float: return "float";
    case Type::S32: return "s32";
    case Type::U32: return "u32";
  }
  return "?";
}

bool parse_type(const std::string& text, Type& out) {
  for (Type t : {Type::Bit, Type::Float, Type::S32, Type::U32}) {
    if (strcasecmp(text.c_str(), type_name(t)) == 0) {
      out = t;
      return true;
    }
  }
  return false;
}

Status parse_value(Type type, const std::string& text, Value& out) {
  out = Value{};
  out.type = type;
  const char* c = text.c_str();
  char* end = nullptr;
  errno = 0;
  switch (type) {
    case Type::Bit:
      if (text == "1" || strcasecmp(c, "true") == 0) out.b = true;
      else if (text == "0" || strcasecmp(c, "false") == 0) out.b = false;
      else return Status::error(-EINVAL, "'" + text + "' is not a bit (use 0, 1, TRUE or FALSE)");
      return {};
    case Type::Float:
      out.f = std::strtod(c, &end);
      if (text.empty() || *end != '\0') return Status::error(-EINVAL, "'" + text + "' is not a float");
      return {};
    case Type::S32: {
      long long v = std::strtoll(c, &end, 0);
      if (text.empty() || *end != '\0' || errno == ERANGE || v < INT32_MIN || v > INT32_MAX)
        return Status::error(-EINVAL, "'" + text + "' is not an s32 (-2147483648..2147483647)");
      out.s = static_cast<std::int32_t>(v);
      return {};
    }
    case Type::U32: {
      unsigned long long v = std::strtoull(c, &end, 0);
      if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE || v > UINT32_MAX)
        return Status::error(-EINVAL, "'" + text + "' is not a u32 (0..4294967295)");
      out.u = static_cast<std::uint32_t>(v);
      return {};
    }
  }
  return Status::error(-EINVAL, "unknown type");
}

std::string format_value(const Value& value) {
  switch (value.type) {
    case Type::Bit: return value.b ? "TRUE" : "FALSE";
    case Type::S32: return std::to_string(value.s);
    case Type::U32: return std::to_string(value.u);
    case Type::Float: {
      char buf[64];
      auto res = std::to_chars(buf, buf + sizeof buf, value.f);
      return std::string(buf, res.ptr);
    }
  }
  return "?";
}

}  // namespace firtp::hal_shim
