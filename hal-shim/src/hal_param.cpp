// hal_param.cpp - parameters: hal_param_new, typed/printf forms, hal_param_*_set.
#include <cstdarg>
#include <cstring>

#include "state.hpp"

namespace firtp::hal_shim::detail {

namespace {

/// Bytes a value of 'type' occupies in its component's memory.
std::size_t type_size(hal_type_t type) {
  switch (type) {
    case HAL_BIT: return sizeof(hal_bit_t);
    case HAL_FLOAT: return sizeof(real_t);
    default: return sizeof(hal_s32_t);
  }
}

}  // namespace

int param_new(const char* name, hal_type_t type, hal_param_dir_t dir, void* data, int comp_id) {
  State& s = state();
  Lock lock(s.mu);
  if (int rc = check_name("param", name); rc < 0) return rc;
  if (type != HAL_BIT && type != HAL_FLOAT && type != HAL_S32 && type != HAL_U32)
    return fail(-EINVAL, "param '%s': invalid type %d", name, static_cast<int>(type));
  if (dir != HAL_RO && dir != HAL_RW)
    return fail(-EINVAL, "param '%s': invalid direction %d", name, static_cast<int>(dir));
  Component* comp = find_comp(comp_id);
  if (comp == nullptr) return fail(-EINVAL, "param '%s': component %d not found", name, comp_id);
  if (comp->ready)
    return fail(-EINVAL, "param '%s': component '%s' is already ready", name, comp->name.c_str());
  if (data == nullptr || !s.arena.contains(data, type_size(type)))
    return fail(-EINVAL, "param '%s': data_addr is not in HAL memory (use hal_malloc)", name);
  if (s.params.count(name) != 0) return fail(-EINVAL, "duplicate param name '%s'", name);
  auto param = std::make_unique<Param>();
  param->name = name;
  param->type = type;
  param->dir = dir;
  param->owner = comp_id;
  param->data = data;
  s.params.emplace(param->name, std::move(param));
  return 0;
}

int param_set(const char* name, hal_type_t type, const void* value) {
  State& s = state();
  Lock lock(s.mu);
  Param* p = name == nullptr ? nullptr : find_param(name);
  if (p == nullptr) return fail(-EINVAL, "param '%s' not found", name == nullptr ? "" : name);
  if (p->type != type)
    return fail(-EINVAL, "param '%s' is %s, not %s", name, type_text(p->type), type_text(type));
  if (p->dir == HAL_RO) return fail(-EINVAL, "param '%s' is read-only", name);
  void* d = p->data;  // only as aligned as its type: no hal_data_u access
  switch (type) {
    case HAL_BIT: *static_cast<hal_bit_t*>(d) = *static_cast<const bool*>(value); break;
    case HAL_FLOAT: *static_cast<volatile real_t*>(d) = *static_cast<const double*>(value); break;
    case HAL_S32: *static_cast<hal_s32_t*>(d) = *static_cast<const std::int32_t*>(value); break;
    default: *static_cast<hal_u32_t*>(d) = *static_cast<const std::uint32_t*>(value); break;
  }
  return 0;
}

}  // namespace firtp::hal_shim::detail

using namespace firtp::hal_shim::detail;

namespace {

/// Formats a printf-style param name, then creates the param.
int param_newf(hal_type_t type, hal_param_dir_t dir, volatile void* data, int comp_id,
               const char* fmt, va_list ap) {
  std::string name = vformat(fmt, ap);
  return report(param_new(name.c_str(), type, dir, const_cast<void*>(data), comp_id));
}

}  // namespace

extern "C" {

int hal_param_new(const char* name, hal_type_t type, hal_param_dir_t dir, void* data_addr,
                  int comp_id) {
  return report(param_new(name, type, dir, data_addr, comp_id));
}

int hal_param_bit_new(const char* name, hal_param_dir_t dir, hal_bit_t* d, int comp_id) {
  return report(param_new(name, HAL_BIT, dir, const_cast<bool*>(d), comp_id));
}
int hal_param_float_new(const char* name, hal_param_dir_t dir, hal_float_t* d, int comp_id) {
  return report(param_new(name, HAL_FLOAT, dir, const_cast<real_t*>(d), comp_id));
}
int hal_param_u32_new(const char* name, hal_param_dir_t dir, hal_u32_t* d, int comp_id) {
  return report(param_new(name, HAL_U32, dir, const_cast<rtapi_u32*>(d), comp_id));
}
int hal_param_s32_new(const char* name, hal_param_dir_t dir, hal_s32_t* d, int comp_id) {
  return report(param_new(name, HAL_S32, dir, const_cast<rtapi_s32*>(d), comp_id));
}

#define FIRTP_PARAM_NEWF(fname, ctype, htype)                                  \
  int fname(hal_param_dir_t dir, ctype* d, int comp_id, const char* fmt, ...) { \
    va_list ap;                                                                 \
    va_start(ap, fmt);                                                          \
    int rc = param_newf(htype, dir, d, comp_id, fmt, ap);                       \
    va_end(ap);                                                                 \
    return rc;                                                                  \
  }
FIRTP_PARAM_NEWF(hal_param_bit_newf, hal_bit_t, HAL_BIT)
FIRTP_PARAM_NEWF(hal_param_float_newf, hal_float_t, HAL_FLOAT)
FIRTP_PARAM_NEWF(hal_param_u32_newf, hal_u32_t, HAL_U32)
FIRTP_PARAM_NEWF(hal_param_s32_newf, hal_s32_t, HAL_S32)
#undef FIRTP_PARAM_NEWF

int hal_param_bit_set(const char* name, int value) {
  bool v = value != 0;
  return report(param_set(name, HAL_BIT, &v));
}
int hal_param_float_set(const char* name, double value) {
  return report(param_set(name, HAL_FLOAT, &value));
}
int hal_param_u32_set(const char* name, unsigned long value) {
  auto v = static_cast<std::uint32_t>(value);
  return report(param_set(name, HAL_U32, &v));
}
int hal_param_s32_set(const char* name, signed long value) {
  auto v = static_cast<std::int32_t>(value);
  return report(param_set(name, HAL_S32, &v));
}
int hal_param_set(const char* name, hal_type_t type, void* value_addr) {
  if (value_addr == nullptr) return report(fail(-EINVAL, "param '%s': no value", name));
  return report(param_set(name, type, value_addr));
}

}  // extern "C"
