// hal_funct.cpp - realtime functions: hal_export_funct and hal_export_functf.
#include <cstdarg>
#include <cstring>

#include "state.hpp"

namespace firtp::hal_shim::detail {

int export_funct(const char* name, void (*fn)(void*, long), void* arg, int uses_fp,
                 int reentrant, int comp_id) {
  State& s = state();
  Lock lock(s.mu);
  if (int rc = check_name("function", name); rc < 0) return rc;
  if (fn == nullptr) return fail(-EINVAL, "function '%s': no code (NULL pointer)", name);
  Component* comp = find_comp(comp_id);
  if (comp == nullptr) return fail(-EINVAL, "function '%s': component %d not found", name, comp_id);
  if (comp->ready)
    return fail(-EINVAL, "function '%s': component '%s' is already ready", name,
                comp->name.c_str());
  if (s.functs.count(name) != 0) return fail(-EINVAL, "duplicate function name '%s'", name);
  auto* times = static_cast<hal_s32_t*>(s.arena.alloc(2 * sizeof(hal_s32_t), alignof(hal_s32_t)));
  if (times == nullptr) return fail(-ENOMEM, "function '%s': HAL memory full", name);
  auto f = std::make_unique<Funct>();
  f->name = name;
  f->fn = fn;
  f->arg = arg;
  f->uses_fp = uses_fp != 0;
  f->reentrant = reentrant != 0;
  f->owner = comp_id;
  f->time = &times[0];
  f->tmax = &times[1];
  // Run-time statistics as params NAME.time (RO) and NAME.tmax (RW), in ns, when they fit.
  if (std::strlen(name) + 5 <= HAL_NAME_LEN) {
    std::string base = name;
    auto* t = const_cast<rtapi_s32*>(f->time);
    auto* m = const_cast<rtapi_s32*>(f->tmax);
    if (int rc = param_new((base + ".time").c_str(), HAL_S32, HAL_RO, t, comp_id); rc < 0) return rc;
    if (int rc = param_new((base + ".tmax").c_str(), HAL_S32, HAL_RW, m, comp_id); rc < 0) {
      s.params.erase(base + ".time");
      return rc;
    }
  }
  s.functs.emplace(f->name, std::move(f));
  return 0;
}

}  // namespace firtp::hal_shim::detail

using namespace firtp::hal_shim::detail;

extern "C" {

int hal_export_funct(const char* name, void (*funct)(void*, long), void* arg, int uses_fp,
                     int reentrant, int comp_id) {
  return report(export_funct(name, funct, arg, uses_fp, reentrant, comp_id));
}

int hal_export_functf(void (*funct)(void*, long), void* arg, int uses_fp, int reentrant,
                      int comp_id, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  std::string name = vformat(fmt, ap);
  va_end(ap);
  return report(export_funct(name.c_str(), funct, arg, uses_fp, reentrant, comp_id));
}

}  // extern "C"
