// hal_comp.cpp - components: hal_init, hal_exit, hal_ready, hal_malloc and friends.
#include "state.hpp"

namespace firtp::hal_shim::detail {

int comp_exit(int comp_id) {
  State& s = state();
  Lock lock(s.mu);
  if (find_comp(comp_id) == nullptr) return fail(-EINVAL, "component %d not found", comp_id);
  for (auto it = s.functs.begin(); it != s.functs.end();) {
    if (it->second->owner == comp_id) {
      remove_funct_from_threads(*it->second);
      it = s.functs.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = s.pins.begin(); it != s.pins.end();) {
    if (it->second->owner == comp_id) {
      unlink_pin(*it->second);
      it = s.pins.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = s.params.begin(); it != s.params.end();)
    it = it->second->owner == comp_id ? s.params.erase(it) : std::next(it);
  s.comps.erase(comp_id);
  return 0;
}

}  // namespace firtp::hal_shim::detail

using namespace firtp::hal_shim::detail;

extern "C" {

int hal_init(const char* name) {
  State& s = state();
  Lock lock(s.mu);
  if (int rc = check_name("component", name); rc < 0) return report(rc);
  for (auto& [id, comp] : s.comps)
    if (comp.name == name) return report(fail(-EINVAL, "duplicate component name '%s'", name));
  Component comp;
  comp.id = s.next_id++;
  comp.name = name;
  comp.module = s.loading_module;
  s.comps[comp.id] = comp;
  return comp.id;
}

int hal_exit(int comp_id) { return report(comp_exit(comp_id)); }

void* hal_malloc(long int size) {
  State& s = state();
  Lock lock(s.mu);
  if (size <= 0) {
    report(fail(-EINVAL, "hal_malloc(%ld): size must be positive", size));
    return nullptr;
  }
  void* p = s.arena.alloc(static_cast<std::size_t>(size));
  if (p == nullptr)
    report(fail(-ENOMEM, "hal_malloc(%ld): HAL memory full (%zu of %zu bytes used; raise "
                         "FIRTP_HAL_SHMEM_SIZE)",
                size, s.arena.used(), s.arena.capacity()));
  return p;
}

int hal_ready(int comp_id) {
  State& s = state();
  Lock lock(s.mu);
  Component* comp = find_comp(comp_id);
  if (comp == nullptr) return report(fail(-EINVAL, "component %d not found", comp_id));
  if (comp->ready) return report(fail(-EINVAL, "component '%s' already ready", comp->name.c_str()));
  comp->ready = true;
  return 0;
}

int hal_set_unready(int comp_id) {
  State& s = state();
  Lock lock(s.mu);
  Component* comp = find_comp(comp_id);
  if (comp == nullptr) return report(fail(-EINVAL, "component %d not found", comp_id));
  comp->ready = false;
  return 0;
}

int hal_unready(int comp_id) { return hal_set_unready(comp_id); }

char* hal_comp_name(int comp_id) {
  State& s = state();
  Lock lock(s.mu);
  Component* comp = find_comp(comp_id);
  return comp == nullptr ? nullptr : comp->name.data();
}

int hal_set_constructor(int comp_id, constructor make) {
  State& s = state();
  Lock lock(s.mu);
  Component* comp = find_comp(comp_id);
  if (comp == nullptr) return report(fail(-EINVAL, "component %d not found", comp_id));
  comp->make = make;
  return 0;
}

}  // extern "C"
