// hal_thread.cpp - threads and their call lists: create, delete, addf, delf.
#include <algorithm>

#include "state.hpp"

namespace firtp::hal_shim::detail {

namespace {

/// Publishes 'items' as the thread's new call list (the old list stays allocated).
void publish(Thread& t, std::vector<Funct*> items) {
  auto list = std::make_unique<FunctList>();
  list->items = std::move(items);
  t.list.store(list.get(), std::memory_order_seq_cst);
  t.lists.push_back(std::move(list));
}

/// The thread's current call list, copied.
std::vector<Funct*> current(const Thread& t) {
  const FunctList* l = t.list.load();
  return l == nullptr ? std::vector<Funct*>{} : l->items;
}

/// Waits until no cycle of 't' that may have seen an older list is still running.
void quiesce(Thread& t) {
  const std::uint64_t seen = t.cycles.load(std::memory_order_seq_cst);
  if (!t.in_cycle.load(std::memory_order_seq_cst) || cycle_thread() == &t) return;
  while (t.cycles.load(std::memory_order_seq_cst) == seen) std::this_thread::yield();
}

/// The thread named 'name', or nullptr after fail(-EINVAL, "thread 'NAME' not found").
Thread* existing_thread(const char* name) {
  Thread* t = name == nullptr ? nullptr : find_thread(name);
  if (t == nullptr) fail(-EINVAL, "thread '%s' not found", name == nullptr ? "" : name);
  return t;
}

/// The function named 'name', or nullptr after fail(-EINVAL, "function 'NAME' not found").
Funct* existing_funct(const char* name) {
  Funct* f = name == nullptr ? nullptr : find_funct(name);
  if (f == nullptr) fail(-EINVAL, "function '%s' not found", name == nullptr ? "" : name);
  return f;
}

/// Adds a thread-owned s32 param (owner 0) for thread statistics.
void thread_param(State& s, const std::string& name, hal_param_dir_t dir, hal_s32_t* data) {
  auto p = std::make_unique<Param>();
  p->name = name;
  p->type = HAL_S32;
  p->dir = dir;
  p->owner = 0;
  p->data = const_cast<rtapi_s32*>(data);
  s.params[name] = std::move(p);
}

}  // namespace

int thread_new(const char* name, unsigned long period, int uses_fp) {
  State& s = state();
  Lock lock(s.mu);
  if (int rc = check_name("thread", name); rc < 0) return rc;
  if (period == 0 || period > 1000000000UL)
    return fail(-EINVAL, "thread '%s': period %lu ns is not in 1..1e9", name, period);
  if (find_thread(name) != nullptr) return fail(-EINVAL, "duplicate thread name '%s'", name);
  if (s.running) return fail(-EBUSY, "thread '%s': cannot create threads while running", name);
  long p = static_cast<long>(period);
  if (s.base_period == 0) {
    s.base_period = p;
  } else if (p < s.base_period) {
    return fail(-EINVAL,
                "thread '%s': period %ld ns is shorter than the base period %ld ns "
                "(create the fastest thread first)",
                name, p, s.base_period);
  } else {
    p = (p + s.base_period / 2) / s.base_period * s.base_period;  // nearest multiple
  }
  auto* times = static_cast<hal_s32_t*>(s.arena.alloc(2 * sizeof(hal_s32_t), alignof(hal_s32_t)));
  if (times == nullptr) return fail(-ENOMEM, "thread '%s': HAL memory full", name);
  auto t = std::make_unique<Thread>();
  t->name = name;
  t->period = p;
  t->uses_fp = uses_fp != 0;
  t->id = s.next_thread_id++;
  t->time = &times[0];
  t->tmax = &times[1];
  if (t->name.size() + 5 <= HAL_NAME_LEN) {
    thread_param(s, t->name + ".time", HAL_RO, t->time);
    thread_param(s, t->name + ".tmax", HAL_RW, t->tmax);
  }
  const int id = t->id;
  s.threads.push_back(std::move(t));
  return id;
}

int thread_delete(const char* name) {
  State& s = state();
  Lock lock(s.mu);
  Thread* t = existing_thread(name);
  if (t == nullptr) return -EINVAL;
  if (s.running) return fail(-EBUSY, "thread '%s': stop threads before deleting one", name);
  for (Funct* f : current(*t)) --f->users;
  s.params.erase(t->name + ".time");
  s.params.erase(t->name + ".tmax");
  auto it = std::find_if(s.threads.begin(), s.threads.end(),
                         [t](const std::unique_ptr<Thread>& p) { return p.get() == t; });
  s.threads.erase(it);
  if (s.threads.empty()) s.base_period = 0;
  return 0;
}

int add_funct(const char* funct, const char* thread, int position) {
  State& s = state();
  Lock lock(s.mu);
  Funct* f = existing_funct(funct);
  if (f == nullptr) return -EINVAL;
  Thread* t = existing_thread(thread);
  if (t == nullptr) return -EINVAL;
  if (position == 0) return fail(-EINVAL, "addf %s: position 0 is invalid (1 first, -1 last)", funct);
  if (f->uses_fp && !t->uses_fp)
    return fail(-EINVAL, "function '%s' uses floating point but thread '%s' does not", funct,
                thread);
  if (!f->reentrant && f->users > 0)
    return fail(-EINVAL, "function '%s' is already in a thread (it is not reentrant)", funct);
  std::vector<Funct*> items = current(*t);
  const long n = static_cast<long>(items.size());
  const long index = position > 0 ? position - 1 : n + 1 + position;
  if (index < 0 || index > n)
    return fail(-EINVAL, "addf %s %s: position %d is out of range (thread has %ld functions)",
                funct, thread, position, n);
  items.insert(items.begin() + index, f);
  publish(*t, std::move(items));
  ++f->users;
  return 0;
}

int del_funct(const char* funct, const char* thread) {
  State& s = state();
  Lock lock(s.mu);
  Funct* f = existing_funct(funct);
  if (f == nullptr) return -EINVAL;
  Thread* t = existing_thread(thread);
  if (t == nullptr) return -EINVAL;
  std::vector<Funct*> items = current(*t);
  auto it = std::find(items.begin(), items.end(), f);
  if (it == items.end())
    return fail(-EINVAL, "function '%s' is not in thread '%s'", funct, thread);
  items.erase(it);
  publish(*t, std::move(items));
  quiesce(*t);
  --f->users;
  return 0;
}

void remove_funct_from_threads(Funct& f) {
  State& s = state();
  Lock lock(s.mu);
  for (auto& t : s.threads) {
    std::vector<Funct*> items = current(*t);
    auto end = std::remove(items.begin(), items.end(), &f);
    if (end == items.end()) continue;
    items.erase(end, items.end());
    publish(*t, std::move(items));
    quiesce(*t);
  }
  f.users = 0;
}

}  // namespace firtp::hal_shim::detail

using namespace firtp::hal_shim::detail;

extern "C" {

int hal_create_thread(const char* name, unsigned long period_nsec, int uses_fp) {
  return report(thread_new(name, period_nsec, uses_fp));
}

int hal_thread_delete(const char* name) { return report(thread_delete(name)); }

int hal_add_funct_to_thread(const char* funct_name, const char* thread_name, int position) {
  return report(add_funct(funct_name, thread_name, position));
}

int hal_del_funct_from_thread(const char* funct_name, const char* thread_name) {
  return report(del_funct(funct_name, thread_name));
}

int hal_start_threads(void) { return report(start_threads()); }

int hal_stop_threads(void) { return report(stop_threads()); }

}  // extern "C"
