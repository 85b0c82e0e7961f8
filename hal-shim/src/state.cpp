// state.cpp - the registry singleton and name lookups.
#include "state.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace firtp::hal_shim::detail {

namespace {

constexpr std::size_t kDefaultArenaBytes = std::size_t{4} << 20;

/// Arena size: $FIRTP_HAL_SHMEM_SIZE (bytes) or 4 MiB.
std::size_t arena_bytes() {
  const char* env = std::getenv("FIRTP_HAL_SHMEM_SIZE");
  if (env == nullptr || *env == '\0') return kDefaultArenaBytes;
  char* end = nullptr;
  unsigned long long v = std::strtoull(env, &end, 0);
  if (end == env || *end != '\0' || v < 4096) return kDefaultArenaBytes;
  return static_cast<std::size_t>(v);
}

/// Stops running threads at process exit so no OS thread calls into unmapped code.
struct ExitGuard {
  ~ExitGuard() {
    State& s = state();
    if (s.running) stop_threads();
  }
};

}  // namespace

State& state() {
  // Never destroyed: components may call in from their own static destructors.
  static State* s = [] {
    auto* p = new State;
    p->arena.init(arena_bytes());
    return p;
  }();
  static ExitGuard guard;
  return *s;
}

Component* find_comp(int id) {
  auto& m = state().comps;
  auto it = m.find(id);
  return it == m.end() ? nullptr : &it->second;
}

template <class T>
static T* find_in(std::map<std::string, std::unique_ptr<T>>& m, const std::string& name) {
  auto it = m.find(name);
  return it == m.end() ? nullptr : it->second.get();
}

Pin* find_pin(const std::string& name) { return find_in(state().pins, name); }
Param* find_param(const std::string& name) { return find_in(state().params, name); }
Signal* find_signal(const std::string& name) { return find_in(state().signals, name); }
Funct* find_funct(const std::string& name) { return find_in(state().functs, name); }

Thread* find_thread(const std::string& name) {
  for (auto& t : state().threads)
    if (t->name == name) return t.get();
  return nullptr;
}

int check_name(const char* kind, const char* name) {
  if (name == nullptr || *name == '\0') return fail(-EINVAL, "no %s name given", kind);
  if (std::strlen(name) > HAL_NAME_LEN)
    return fail(-EINVAL, "%s name '%s' is too long (at most %d characters)", kind, name,
                HAL_NAME_LEN);
  return 0;
}

const char* type_text(hal_type_t type) {
  switch (type) {
    case HAL_BIT: return "bit";
    case HAL_FLOAT: return "float";
    case HAL_S32: return "s32";
    case HAL_U32: return "u32";
    case HAL_PORT: return "port";
    default: return "?";
  }
}

std::string vformat(const char* fmt, va_list ap) {
  va_list copy;
  va_copy(copy, ap);
  int n = std::vsnprintf(nullptr, 0, fmt, copy);
  va_end(copy);
  if (n < 0) return fmt;
  std::string out(static_cast<std::size_t>(n) + 1, '\0');
  std::vsnprintf(out.data(), out.size(), fmt, ap);
  out.resize(static_cast<std::size_t>(n));
  return out;
}

}  // namespace firtp::hal_shim::detail
