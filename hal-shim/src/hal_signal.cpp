// hal_signal.cpp - signals and links: a linked pin points at its signal's storage.
#include "state.hpp"

namespace firtp::hal_shim::detail {

int signal_new(const char* name, hal_type_t type) {
  State& s = state();
  Lock lock(s.mu);
  if (int rc = check_name("signal", name); rc < 0) return rc;
  if (type != HAL_BIT && type != HAL_FLOAT && type != HAL_S32 && type != HAL_U32)
    return fail(-EINVAL, "signal '%s': invalid type %d", name, static_cast<int>(type));
  if (s.signals.count(name) != 0) return fail(-EINVAL, "duplicate signal name '%s'", name);
  auto* data = static_cast<hal_data_u*>(s.arena.alloc(sizeof(hal_data_u), alignof(hal_data_u)));
  if (data == nullptr) return fail(-ENOMEM, "signal '%s': HAL memory full", name);
  auto sig = std::make_unique<Signal>();
  sig->name = name;
  sig->type = type;
  sig->data = data;
  s.signals.emplace(sig->name, std::move(sig));
  return 0;
}

int signal_delete(const char* name) {
  State& s = state();
  Lock lock(s.mu);
  Signal* sig = name == nullptr ? nullptr : find_signal(name);
  if (sig == nullptr) return fail(-EINVAL, "signal '%s' not found", name == nullptr ? "" : name);
  for (auto& [pname, pin] : s.pins)
    if (pin->sig == sig) unlink_pin(*pin);
  s.signals.erase(sig->name);
  return 0;
}

int link_pin(const char* pin_name, const char* sig_name) {
  State& s = state();
  Lock lock(s.mu);
  Pin* pin = pin_name == nullptr ? nullptr : find_pin(pin_name);
  if (pin == nullptr) return fail(-EINVAL, "pin '%s' not found", pin_name ? pin_name : "");
  Signal* sig = sig_name == nullptr ? nullptr : find_signal(sig_name);
  if (sig == nullptr) return fail(-EINVAL, "signal '%s' not found", sig_name ? sig_name : "");
  if (pin->sig == sig) return 0;
  if (pin->sig != nullptr)
    return fail(-EINVAL, "pin '%s' is already linked to signal '%s'", pin_name,
                pin->sig->name.c_str());
  if (pin->type != sig->type)
    return fail(-EINVAL, "type mismatch: pin '%s' is %s but signal '%s' is %s", pin_name,
                type_text(pin->type), sig_name, type_text(sig->type));
  if ((pin->dir == HAL_OUT || pin->dir == HAL_IO) && sig->writers > 0) {
    for (auto& [n, other] : s.pins)
      if (other->sig == sig && other->dir == HAL_OUT)
        return fail(-EINVAL, "signal '%s' already has output pin '%s' (cannot add '%s')",
                    sig_name, n.c_str(), pin_name);
  }
  if (pin->dir == HAL_OUT && sig->bidirs > 0)
    return fail(-EINVAL, "signal '%s' already has I/O pins (cannot add output pin '%s')",
                sig_name, pin_name);
  // As HAL's hal_link: the first pin that could drive the signal seeds it with its value (also an
  // output pin joining a signal that only has readers, e.g. a bridge loaded again).
  if ((pin->dir != HAL_IN || sig->readers == 0) && sig->writers == 0 && sig->bidirs == 0)
    copy_value(sig->type, sig->data, pin->dummy);
  __atomic_store_n(pin->ptr_addr, static_cast<void*>(sig->data), __ATOMIC_RELEASE);
  pin->sig = sig;
  if (pin->dir == HAL_OUT) ++sig->writers;
  else if (pin->dir == HAL_IN) ++sig->readers;
  else ++sig->bidirs;
  return 0;
}

int unlink_pin(Pin& pin) {
  Signal* sig = pin.sig;
  if (sig == nullptr) return 0;
  copy_value(pin.type, pin.dummy, sig->data);  // keeps the last value, as HAL does
  __atomic_store_n(pin.ptr_addr, static_cast<void*>(pin.dummy), __ATOMIC_RELEASE);
  if (pin.dir == HAL_OUT) --sig->writers;
  else if (pin.dir == HAL_IN) --sig->readers;
  else --sig->bidirs;
  pin.sig = nullptr;
  return 0;
}

}  // namespace firtp::hal_shim::detail

using namespace firtp::hal_shim::detail;

extern "C" {

int hal_signal_new(const char* name, hal_type_t type) { return report(signal_new(name, type)); }

int hal_signal_delete(const char* name) { return report(signal_delete(name)); }

int hal_link(const char* pin_name, const char* sig_name) {
  return report(link_pin(pin_name, sig_name));
}

int hal_unlink(const char* pin_name) {
  State& s = state();
  Lock lock(s.mu);
  Pin* pin = pin_name == nullptr ? nullptr : find_pin(pin_name);
  if (pin == nullptr) return report(fail(-EINVAL, "pin '%s' not found", pin_name ? pin_name : ""));
  return unlink_pin(*pin);
}

int hal_get_pin_value_by_name(const char* name, hal_type_t* type, hal_data_u** data,
                              bool* connected) {
  State& s = state();
  Lock lock(s.mu);
  Pin* pin = name == nullptr ? nullptr : find_pin(name);
  if (pin == nullptr) return -1;
  if (type != nullptr) *type = pin->type;
  if (data != nullptr) *data = pin->sig != nullptr ? pin->sig->data : pin->dummy;
  if (connected != nullptr) *connected = pin->sig != nullptr;
  return 0;
}

int hal_get_signal_value_by_name(const char* name, hal_type_t* type, hal_data_u** data,
                                 bool* has_writers) {
  State& s = state();
  Lock lock(s.mu);
  Signal* sig = name == nullptr ? nullptr : find_signal(name);
  if (sig == nullptr) return -1;
  if (type != nullptr) *type = sig->type;
  if (data != nullptr) *data = sig->data;
  if (has_writers != nullptr) *has_writers = sig->writers > 0;
  return 0;
}

int hal_get_param_value_by_name(const char* name, hal_type_t* type, hal_data_u** data) {
  State& s = state();
  Lock lock(s.mu);
  Param* p = name == nullptr ? nullptr : find_param(name);
  if (p == nullptr) return -1;
  if (type != nullptr) *type = p->type;
  if (data != nullptr) *data = static_cast<hal_data_u*>(p->data);
  return 0;
}

}  // extern "C"
