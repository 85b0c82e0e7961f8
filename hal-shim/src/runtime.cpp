// runtime.cpp - the C++ control API (halcmd's verbs) over the registry.
#include "firtp/hal_shim/runtime.hpp"

#include "state.hpp"

namespace firtp::hal_shim {

using namespace detail;

namespace {

/// Status for an internal return code: its last error message when negative.
Status status(int rc) {
  if (rc >= 0) return {};
  return Status::error(rc, last_error_text());
}

/// Reads a value of 'type' from HAL storage (params may be only as aligned as their type).
/// Relaxed atomic loads: a realtime thread may be writing the cell at the same time.
Value read_cell(hal_type_t type, const void* cell) {
  Value v;
  v.type = static_cast<Type>(type);
  switch (type) {
    case HAL_BIT: v.b = __atomic_load_n(static_cast<const hal_bit_t*>(cell), __ATOMIC_RELAXED); break;
    case HAL_FLOAT: __atomic_load(static_cast<const volatile double*>(cell), &v.f, __ATOMIC_RELAXED); break;
    case HAL_S32: v.s = __atomic_load_n(static_cast<const hal_s32_t*>(cell), __ATOMIC_RELAXED); break;
    default: v.u = __atomic_load_n(static_cast<const hal_u32_t*>(cell), __ATOMIC_RELAXED); break;
  }
  return v;
}

/// Writes a value (already of the cell's type) into HAL storage (relaxed atomic store).
void write_cell(const Value& v, void* cell) {
  switch (v.type) {
    case Type::Bit: __atomic_store_n(static_cast<hal_bit_t*>(cell), v.b, __ATOMIC_RELAXED); break;
    case Type::Float: {
      double f = v.f;
      __atomic_store(static_cast<volatile double*>(cell), &f, __ATOMIC_RELAXED);
      break;
    }
    case Type::S32: __atomic_store_n(static_cast<hal_s32_t*>(cell), v.s, __ATOMIC_RELAXED); break;
    case Type::U32: __atomic_store_n(static_cast<hal_u32_t*>(cell), v.u, __ATOMIC_RELAXED); break;
  }
}

/// Where a pin's value currently lives.
const hal_data_u* pin_cell(const Pin& p) { return p.sig != nullptr ? p.sig->data : p.dummy; }

std::string owner_name(int id) {
  Component* c = find_comp(id);
  return c != nullptr ? c->name : std::string();
}

bool is_arrow(const std::string& t) { return t == "=>" || t == "<=" || t == "<=>"; }

}  // namespace

Status new_signal(const std::string& name, Type type) {
  return status(signal_new(name.c_str(), static_cast<hal_type_t>(type)));
}

Status delete_signal(const std::string& name) { return status(signal_delete(name.c_str())); }

Status link(const std::string& pin, const std::string& signal) {
  return status(link_pin(pin.c_str(), signal.c_str()));
}

Status unlink(const std::string& pin) {
  State& s = state();
  Lock lock(s.mu);
  Pin* p = find_pin(pin);
  if (p == nullptr) return Status::error(-EINVAL, "pin '" + pin + "' not found");
  return status(unlink_pin(*p));
}

Status net(const std::string& signal, const std::vector<std::string>& tokens) {
  State& s = state();
  Lock lock(s.mu);
  std::vector<Pin*> pins;
  for (const auto& t : tokens) {
    if (is_arrow(t)) continue;
    Pin* p = find_pin(t);
    if (p == nullptr) return Status::error(-EINVAL, "pin '" + t + "' not found");
    pins.push_back(p);
  }
  if (pins.empty()) return Status::error(-EINVAL, "net " + signal + ": no pins given");
  if (find_pin(signal) != nullptr)
    return Status::error(-EINVAL, "signal name '" + signal + "' is also the name of a pin");
  Signal* sig = find_signal(signal);
  const hal_type_t type = sig != nullptr ? sig->type : pins.front()->type;
  int writers = sig != nullptr ? sig->writers : 0;
  for (Pin* p : pins) {  // check everything before linking anything
    if (p->type != type)
      return Status::error(-EINVAL, "type mismatch: pin '" + p->name + "' is " +
                                        type_text(p->type) + " but signal '" + signal + "' is " +
                                        type_text(type));
    if (p->sig != nullptr && p->sig->name != signal)
      return Status::error(-EINVAL, "pin '" + p->name + "' is already linked to signal '" +
                                        p->sig->name + "'");
    if (p->dir == HAL_OUT && p->sig == nullptr && ++writers > 1)
      return Status::error(-EINVAL, "signal '" + signal + "' would have more than one output pin (" +
                                        p->name + ")");
  }
  if (sig == nullptr) {
    if (Status st = status(signal_new(signal.c_str(), type)); !st.ok()) return st;
  }
  for (Pin* p : pins)
    if (Status st = status(link_pin(p->name.c_str(), signal.c_str())); !st.ok()) return st;
  return {};
}

Status set_value(const std::string& name, const std::string& text) {
  State& s = state();
  Lock lock(s.mu);
  Value v;
  if (Param* p = find_param(name)) {
    if (p->dir == HAL_RO) return Status::error(-EPERM, "param '" + name + "' is read-only");
    if (Status st = parse_value(static_cast<Type>(p->type), text, v); !st.ok())
      return Status::error(st.code, "setp " + name + ": " + st.message);
    write_cell(v, p->data);
    return {};
  }
  Pin* p = find_pin(name);
  if (p == nullptr) return Status::error(-EINVAL, "no pin or param named '" + name + "'");
  if (p->dir == HAL_OUT)
    return Status::error(-EPERM, "pin '" + name + "' is an output: only its component writes it");
  if (p->sig != nullptr)
    return Status::error(-EPERM, "pin '" + name + "' is linked to signal '" + p->sig->name +
                                     "': use sets " + p->sig->name);
  if (Status st = parse_value(static_cast<Type>(p->type), text, v); !st.ok())
    return Status::error(st.code, "setp " + name + ": " + st.message);
  write_cell(v, p->dummy);
  return {};
}

Status set_signal(const std::string& name, const std::string& text) {
  State& s = state();
  Lock lock(s.mu);
  Signal* sig = find_signal(name);
  if (sig == nullptr) return Status::error(-EINVAL, "signal '" + name + "' not found");
  if (sig->writers > 0) {
    for (auto& [pname, p] : s.pins)
      if (p->sig == sig && p->dir == HAL_OUT)
        return Status::error(-EPERM, "signal '" + name + "' is written by pin '" + pname +
                                         "': sets would be overwritten");
  }
  Value v;
  if (Status st = parse_value(static_cast<Type>(sig->type), text, v); !st.ok())
    return Status::error(st.code, "sets " + name + ": " + st.message);
  write_cell(v, sig->data);
  return {};
}

Status get_value(const std::string& name, Value& out) {
  State& s = state();
  Lock lock(s.mu);
  if (Param* p = find_param(name)) {
    out = read_cell(p->type, p->data);
    return {};
  }
  if (Pin* p = find_pin(name)) {
    out = read_cell(p->type, pin_cell(*p));
    return {};
  }
  return Status::error(-EINVAL, "no pin or param named '" + name + "'");
}

Status get_signal(const std::string& name, Value& out) {
  State& s = state();
  Lock lock(s.mu);
  Signal* sig = find_signal(name);
  if (sig == nullptr) return Status::error(-EINVAL, "signal '" + name + "' not found");
  out = read_cell(sig->type, sig->data);
  return {};
}

Status new_thread(const std::string& name, long period_ns, bool uses_fp) {
  if (period_ns <= 0)
    return Status::error(-EINVAL, "thread '" + name + "': period must be positive");
  return status(thread_new(name.c_str(), static_cast<unsigned long>(period_ns), uses_fp ? 1 : 0));
}

Status delete_thread(const std::string& name) { return status(thread_delete(name.c_str())); }

Status add_funct(const std::string& funct, const std::string& thread, int position) {
  return status(detail::add_funct(funct.c_str(), thread.c_str(), position));
}

Status del_funct(const std::string& funct, const std::string& thread) {
  return status(detail::del_funct(funct.c_str(), thread.c_str()));
}

Status start_threads() { return status(detail::start_threads()); }

Status stop_threads() { return status(detail::stop_threads()); }

bool threads_running() {
  State& s = state();
  Lock lock(s.mu);
  return s.running;
}

Status step(std::uint64_t ticks) { return status(step_ticks(ticks)); }

long base_period_ns() {
  State& s = state();
  Lock lock(s.mu);
  return s.base_period;
}

std::uint64_t thread_cycles(const std::string& name) {
  State& s = state();
  Lock lock(s.mu);
  Thread* t = find_thread(name);
  return t != nullptr ? t->cycles.load() : 0;
}

void set_rt_priority(int priority) {
  State& s = state();
  Lock lock(s.mu);
  s.rt_priority = priority < 0 ? 0 : priority;
}

std::vector<CompInfo> components() {
  State& s = state();
  Lock lock(s.mu);
  std::vector<CompInfo> out;
  for (auto& [id, c] : s.comps) out.push_back({id, c.name, c.module, c.ready});
  return out;
}

std::vector<PinInfo> pins() {
  State& s = state();
  Lock lock(s.mu);
  std::vector<PinInfo> out;
  for (auto& [name, p] : s.pins)
    out.push_back({name, owner_name(p->owner), p->sig != nullptr ? p->sig->name : "",
                   static_cast<Type>(p->type), static_cast<PinDir>(p->dir),
                   read_cell(p->type, pin_cell(*p))});
  return out;
}

std::vector<ParamInfo> params() {
  State& s = state();
  Lock lock(s.mu);
  std::vector<ParamInfo> out;
  for (auto& [name, p] : s.params)
    out.push_back({name, owner_name(p->owner), static_cast<Type>(p->type),
                   static_cast<ParamDir>(p->dir), read_cell(p->type, p->data)});
  return out;
}

std::vector<SignalInfo> signals() {
  State& s = state();
  Lock lock(s.mu);
  std::vector<SignalInfo> out;
  for (auto& [name, sig] : s.signals) {
    SignalInfo info{name, static_cast<Type>(sig->type), read_cell(sig->type, sig->data), "", {}, {}};
    for (auto& [pname, p] : s.pins) {
      if (p->sig != sig.get()) continue;
      if (p->dir == HAL_OUT) info.writer = pname;
      else if (p->dir == HAL_IN) info.readers.push_back(pname);
      else info.bidirs.push_back(pname);
    }
    out.push_back(std::move(info));
  }
  return out;
}

std::vector<FunctInfo> functs() {
  State& s = state();
  Lock lock(s.mu);
  std::vector<FunctInfo> out;
  for (auto& [name, f] : s.functs)
    out.push_back({name, owner_name(f->owner), f->users, f->uses_fp, f->reentrant,
                   __atomic_load_n(f->time, __ATOMIC_RELAXED),
                   __atomic_load_n(f->tmax, __ATOMIC_RELAXED)});
  return out;
}

std::vector<ThreadInfo> threads() {
  State& s = state();
  Lock lock(s.mu);
  std::vector<ThreadInfo> out;
  for (auto& t : s.threads) {
    ThreadInfo info{t->name, t->period, t->uses_fp, t->cycles.load(), t->overruns.load(),
                    __atomic_load_n(t->time, __ATOMIC_RELAXED),
                    __atomic_load_n(t->tmax, __ATOMIC_RELAXED), {}};
    if (const FunctList* l = t->list.load())
      for (Funct* f : l->items) info.functs.push_back(f->name);
    out.push_back(std::move(info));
  }
  return out;
}

std::size_t arena_used() {
  State& s = state();
  Lock lock(s.mu);
  return s.arena.used();
}

std::size_t arena_size() {
  State& s = state();
  Lock lock(s.mu);
  return s.arena.capacity();
}

const std::string& last_error() { return last_error_text(); }

void reset() {
  State& s = state();
  Lock lock(s.mu);
  detail::stop_threads();
  unload_module("all");
  while (!s.comps.empty()) comp_exit(s.comps.begin()->first);
  while (!s.signals.empty()) signal_delete(s.signals.begin()->first.c_str());
  while (!s.threads.empty()) thread_delete(s.threads.front()->name.c_str());
  s.params.clear();
  shmem_clear();
  s.arena.rewind();
  s.base_period = 0;
  s.rt_priority = 0;
  clear_error();
}

}  // namespace firtp::hal_shim
