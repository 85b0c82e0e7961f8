// hal_pin.cpp - pins: hal_pin_new and the typed/printf forms.
#include <cstdarg>
#include <type_traits>

#include "state.hpp"

namespace firtp::hal_shim::detail {

int pin_new(const char* name, hal_type_t type, hal_pin_dir_t dir, void** ptr_addr, int comp_id) {
  State& s = state();
  Lock lock(s.mu);
  if (int rc = check_name("pin", name); rc < 0) return rc;
  if (type == HAL_PORT) return fail(-EINVAL, "pin '%s': port pins are not supported", name);
  if (type != HAL_BIT && type != HAL_FLOAT && type != HAL_S32 && type != HAL_U32)
    return fail(-EINVAL, "pin '%s': invalid type %d", name, static_cast<int>(type));
  if (dir != HAL_IN && dir != HAL_OUT && dir != HAL_IO)
    return fail(-EINVAL, "pin '%s': invalid direction %d", name, static_cast<int>(dir));
  Component* comp = find_comp(comp_id);
  if (comp == nullptr) return fail(-EINVAL, "pin '%s': component %d not found", name, comp_id);
  if (comp->ready)
    return fail(-EINVAL, "pin '%s': component '%s' is already ready", name, comp->name.c_str());
  if (ptr_addr == nullptr || !s.arena.contains(ptr_addr, sizeof(void*)))
    return fail(-EINVAL, "pin '%s': data_ptr_addr is not in HAL memory (use hal_malloc)", name);
  if (s.pins.count(name) != 0) return fail(-EINVAL, "duplicate pin name '%s'", name);
  auto* dummy = static_cast<hal_data_u*>(s.arena.alloc(sizeof(hal_data_u), alignof(hal_data_u)));
  if (dummy == nullptr) return fail(-ENOMEM, "pin '%s': HAL memory full", name);
  auto pin = std::make_unique<Pin>();
  pin->name = name;
  pin->type = type;
  pin->dir = dir;
  pin->owner = comp_id;
  pin->ptr_addr = ptr_addr;
  pin->dummy = dummy;
  __atomic_store_n(ptr_addr, static_cast<void*>(dummy), __ATOMIC_RELEASE);
  s.pins.emplace(pin->name, std::move(pin));
  return 0;
}

}  // namespace firtp::hal_shim::detail

using namespace firtp::hal_shim::detail;

namespace {

/// Formats a printf-style pin name, then creates the pin.
int pin_newf(hal_type_t type, hal_pin_dir_t dir, void** ptr_addr, int comp_id, const char* fmt,
             va_list ap) {
  std::string name = vformat(fmt, ap);
  return report(pin_new(name.c_str(), type, dir, ptr_addr, comp_id));
}

template <class T>
void** as_void_pp(T** p) {
  return reinterpret_cast<void**>(const_cast<std::remove_volatile_t<T>**>(p));
}

}  // namespace

extern "C" {

int hal_pin_new(const char* name, hal_type_t type, hal_pin_dir_t dir, void** data_ptr_addr,
                int comp_id) {
  return report(pin_new(name, type, dir, data_ptr_addr, comp_id));
}

int hal_pin_bit_new(const char* name, hal_pin_dir_t dir, hal_bit_t** p, int comp_id) {
  return hal_pin_new(name, HAL_BIT, dir, as_void_pp(p), comp_id);
}
int hal_pin_float_new(const char* name, hal_pin_dir_t dir, hal_float_t** p, int comp_id) {
  return hal_pin_new(name, HAL_FLOAT, dir, as_void_pp(p), comp_id);
}
int hal_pin_u32_new(const char* name, hal_pin_dir_t dir, hal_u32_t** p, int comp_id) {
  return hal_pin_new(name, HAL_U32, dir, as_void_pp(p), comp_id);
}
int hal_pin_s32_new(const char* name, hal_pin_dir_t dir, hal_s32_t** p, int comp_id) {
  return hal_pin_new(name, HAL_S32, dir, as_void_pp(p), comp_id);
}

#define FIRTP_PIN_NEWF(fname, ctype, htype)                                   \
  int fname(hal_pin_dir_t dir, ctype** p, int comp_id, const char* fmt, ...) { \
    va_list ap;                                                                \
    va_start(ap, fmt);                                                         \
    int rc = pin_newf(htype, dir, as_void_pp(p), comp_id, fmt, ap);            \
    va_end(ap);                                                                \
    return rc;                                                                 \
  }
FIRTP_PIN_NEWF(hal_pin_bit_newf, hal_bit_t, HAL_BIT)
FIRTP_PIN_NEWF(hal_pin_float_newf, hal_float_t, HAL_FLOAT)
FIRTP_PIN_NEWF(hal_pin_u32_newf, hal_u32_t, HAL_U32)
FIRTP_PIN_NEWF(hal_pin_s32_newf, hal_s32_t, HAL_S32)
#undef FIRTP_PIN_NEWF

}  // extern "C"
