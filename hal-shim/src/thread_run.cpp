// thread_run.cpp - the realtime path: a thread's cycle, its OS thread loop, start/stop, step.
#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <climits>
#include <cstring>

#include "state.hpp"

namespace firtp::hal_shim::detail {

namespace {

__attribute__((tls_model("initial-exec"))) thread_local const Thread* t_cycle = nullptr;

long long now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<long long>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

/// Stores a duration in a time/tmax param pair (saturating at INT32_MAX ns).
void record(hal_s32_t* time, hal_s32_t* tmax, long long ns) {
  const auto v = static_cast<rtapi_s32>(std::min<long long>(ns, INT32_MAX));
  __atomic_store_n(time, v, __ATOMIC_RELAXED);  // read concurrently by show/getp
  if (v > __atomic_load_n(tmax, __ATOMIC_RELAXED)) __atomic_store_n(tmax, v, __ATOMIC_RELAXED);
}

void add_ns(timespec& ts, long ns) {
  ts.tv_nsec += ns;
  while (ts.tv_nsec >= 1000000000L) {
    ts.tv_nsec -= 1000000000L;
    ++ts.tv_sec;
  }
}

bool later(const timespec& a, const timespec& b) {
  return a.tv_sec != b.tv_sec ? a.tv_sec > b.tv_sec : a.tv_nsec > b.tv_nsec;
}

/// OS thread body: sleep to each absolute deadline, run a cycle, count overruns.
void thread_main(Thread* t, int priority) {
  std::string short_name = t->name.substr(0, 15);
  pthread_setname_np(pthread_self(), short_name.c_str());
  if (priority > 0) {
    sched_param sp{};
    sp.sched_priority = priority;
    if (int rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp); rc != 0)
      rtapi_print_msg(RTAPI_MSG_WARN, "HAL: WARNING: thread '%s': SCHED_FIFO %d refused: %s\n",
                      t->name.c_str(), priority, std::strerror(rc));
  }
  timespec next{};
  clock_gettime(CLOCK_MONOTONIC, &next);
  while (!t->stop.load(std::memory_order_relaxed)) {
    add_ns(next, t->period);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr) == EINTR) {
    }
    if (t->stop.load(std::memory_order_relaxed)) break;
    run_cycle(*t);
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    timespec due = next;
    add_ns(due, t->period);
    if (later(now, due)) {  // missed at least one deadline: count it and resynchronise
      t->overruns.fetch_add(1, std::memory_order_relaxed);
      next = now;
    }
  }
}

}  // namespace

const Thread* cycle_thread() { return t_cycle; }

void run_cycle(Thread& t) {
  t.in_cycle.store(true, std::memory_order_seq_cst);
  const FunctList* list = t.list.load(std::memory_order_seq_cst);
  const Thread* outer = t_cycle;
  t_cycle = &t;
  const long long start = now_ns();
  long long prev = start;
  if (list != nullptr) {
    for (Funct* f : list->items) {
      f->fn(f->arg, t.period);
      const long long end = now_ns();
      record(f->time, f->tmax, end - prev);
      prev = end;
    }
  }
  record(t.time, t.tmax, prev - start);
  t_cycle = outer;
  t.in_cycle.store(false, std::memory_order_seq_cst);
  t.cycles.fetch_add(1, std::memory_order_seq_cst);
}

int start_threads() {
  State& s = state();
  Lock lock(s.mu);
  if (s.running) return 0;
  int priority = s.rt_priority;
  for (auto& t : s.threads) {  // creation order = fastest first = highest priority
    t->stop.store(false);
    t->worker = std::thread(thread_main, t.get(), priority);
    if (priority > 1) --priority;
  }
  s.running = true;
  return 0;
}

int stop_threads() {
  State& s = state();
  Lock lock(s.mu);
  if (!s.running) return 0;
  for (auto& t : s.threads) t->stop.store(true);
  for (auto& t : s.threads)
    if (t->worker.joinable()) t->worker.join();
  s.running = false;
  return 0;
}

int step_ticks(std::uint64_t ticks) {
  State& s = state();
  Lock lock(s.mu);
  if (s.running) return fail(-EBUSY, "threads are running in real time: 'stop' before stepping");
  if (s.threads.empty())
    return fail(-EINVAL, "no thread to step (create one: newthread NAME PERIOD_NS)");
  std::vector<Thread*> order;
  for (auto& t : s.threads) order.push_back(t.get());
  std::stable_sort(order.begin(), order.end(),
                   [](const Thread* a, const Thread* b) { return a->period < b->period; });
  for (std::uint64_t i = 0; i < ticks; ++i) {
    for (Thread* t : order) {
      t->sim_accum += s.base_period;
      if (t->sim_accum >= t->period) {
        t->sim_accum -= t->period;
        run_cycle(*t);
      }
    }
  }
  return 0;
}

}  // namespace firtp::hal_shim::detail
