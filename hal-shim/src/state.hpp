// state.hpp - the shim's registry: components, pins, params, signals, functions, threads, modules.
//
// Everything here is configuration-time data guarded by State::mu (recursive: C API calls made by
// a component inside rtapi_app_main nest inside loadrt).  The realtime path (Thread::run_cycle)
// touches only Thread/Funct atomics and arena memory, never the mutex or the heap.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "arena.hpp"
#include "hal.h"

namespace firtp::hal_shim::detail {

struct Signal;

struct Component {
  int id = 0;
  std::string name;
  std::string module;  // loadrt name of the module whose rtapi_app_main created it
  bool ready = false;
  constructor make = nullptr;
};

struct Pin {
  std::string name;
  hal_type_t type = HAL_FLOAT;
  hal_pin_dir_t dir = HAL_IN;
  int owner = 0;
  void** ptr_addr = nullptr;    // the component's pointer (in the arena)
  hal_data_u* dummy = nullptr;  // where the pointer points while unlinked (in the arena)
  Signal* sig = nullptr;
};

struct Param {
  std::string name;
  hal_type_t type = HAL_FLOAT;
  hal_param_dir_t dir = HAL_RW;
  int owner = 0;
  void* data = nullptr;  // in the arena
};

struct Signal {
  std::string name;
  hal_type_t type = HAL_FLOAT;
  hal_data_u* data = nullptr;  // in the arena
  int readers = 0, writers = 0, bidirs = 0;
};

struct Funct {
  std::string name;
  void (*fn)(void*, long) = nullptr;
  void* arg = nullptr;
  bool uses_fp = true, reentrant = false;
  int owner = 0;
  int users = 0;
  hal_s32_t* time = nullptr;  // param name.time: last run, ns
  hal_s32_t* tmax = nullptr;  // param name.tmax: longest run, ns (RW: setp 0 resets)
};

/// A thread's call list; immutable once published (replaced whole, old ones kept until the
/// thread is deleted so a cycle in flight never sees freed memory).
struct FunctList {
  std::vector<Funct*> items;
};

struct Thread {
  std::string name;
  long period = 0;
  bool uses_fp = true;
  int id = 0;
  std::atomic<const FunctList*> list{nullptr};
  std::vector<std::unique_ptr<FunctList>> lists;  // every list ever published
  std::thread worker;
  std::atomic<bool> stop{false};
  std::atomic<bool> in_cycle{false};
  std::atomic<std::uint64_t> cycles{0};
  std::atomic<std::uint64_t> overruns{0};
  hal_s32_t* time = nullptr;  // param thread.time
  hal_s32_t* tmax = nullptr;  // param thread.tmax
  long sim_accum = 0;         // step(): ns accumulated towards the next run
};

struct Module {
  std::string name, path;
  void* handle = nullptr;             // nullptr for built-in 'threads'
  std::vector<char*> owned_strings;   // strdup'd string module parameters
  /// Every parameter element loadrt set, with its value before: restored (last first) before
  /// dlclose. dlclose may leave the module mapped (a C++ module with unique symbols stays), and
  /// its statics would keep this load's values, string pointers into the freed owned_strings.
  struct Saved {
    void* address;
    char kind;  // 'i', 'l', 's'
    long integer;
    char* string;
  };
  std::vector<Saved> saved;
  std::vector<std::string> threads;   // built-in 'threads': the threads it created
};

struct Shmem {
  int id = 0, key = 0, refs = 0;
  std::size_t size = 0;
  void* ptr = nullptr;
};

struct State {
  std::recursive_mutex mu;
  Arena arena;
  int next_id = 1;  // component/module ids (rtapi_init, hal_init)
  int next_shmem_id = 1;
  int next_thread_id = 1;
  std::map<int, Component> comps;
  std::map<std::string, std::unique_ptr<Pin>> pins;
  std::map<std::string, std::unique_ptr<Param>> params;
  std::map<std::string, std::unique_ptr<Signal>> signals;
  std::map<std::string, std::unique_ptr<Funct>> functs;
  std::vector<std::unique_ptr<Thread>> threads;  // creation order
  std::vector<Module> modules;                    // load order
  std::map<int, Shmem> shmem;                     // by id
  std::string loading_module;                     // set while a module's rtapi_app_main runs
  long base_period = 0;
  bool running = false;
  int rt_priority = 0;
};

/// The process-wide registry (arena mapped on first use: $FIRTP_HAL_SHMEM_SIZE or 4 MiB).
State& state();
using Lock = std::lock_guard<std::recursive_mutex>;

// ---- errors (errors.cpp) ----
/// Records "message" as the last error of this thread and returns 'code'.
int fail(int code, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
/// For C entry points: prints the last error as "HAL: ERROR: ..." when rc < 0; returns rc.
int report(int rc);
/// Clears this thread's last error.
void clear_error();
/// This thread's last error message.
std::string& last_error_text();

// ---- lookups (state.cpp) ----
Component* find_comp(int id);
Pin* find_pin(const std::string& name);
Param* find_param(const std::string& name);
Signal* find_signal(const std::string& name);
Funct* find_funct(const std::string& name);
Thread* find_thread(const std::string& name);
/// Checks a name is non-empty and at most HAL_NAME_LEN; 0 or fail(-EINVAL).
int check_name(const char* kind, const char* name);
/// "bit", "float", "s32", "u32" or "port"/"?".
const char* type_text(hal_type_t type);
/// Copies one value of 'type' between HAL storage cells.
inline void copy_value(hal_type_t type, hal_data_u* dst, const hal_data_u* src) {
  switch (type) {
    case HAL_BIT: dst->b = src->b; break;
    case HAL_FLOAT: dst->f = src->f; break;
    case HAL_S32: dst->s = src->s; break;
    default: dst->u = src->u; break;
  }
}
/// vsnprintf into a std::string.
std::string vformat(const char* fmt, va_list ap);

// ---- internal operations: C entry points wrap them with report(); runtime.cpp with Status ----
/// hal_exit: removes the component's functions (from threads first), pins, params.
int comp_exit(int comp_id);
/// hal_pin_new: validates, allocates the dummy, points *ptr_addr at it.
int pin_new(const char* name, hal_type_t type, hal_pin_dir_t dir, void** ptr_addr, int comp_id);
/// hal_param_new: validates and registers storage the component allocated.
int param_new(const char* name, hal_type_t type, hal_param_dir_t dir, void* data, int comp_id);
/// hal_param_set: *value is a bool/double/int32/uint32 matching 'type'.
int param_set(const char* name, hal_type_t type, const void* value);
/// hal_signal_new: storage from the arena, initially 0.
int signal_new(const char* name, hal_type_t type);
/// hal_signal_delete: unlinks its pins first.
int signal_delete(const char* name);
/// hal_link: checks types and writers, repoints the pin at the signal.
int link_pin(const char* pin_name, const char* sig_name);
/// hal_unlink: the pin keeps the signal's value in its dummy.
int unlink_pin(Pin& pin);
/// hal_export_funct, plus its NAME.time/NAME.tmax params.
int export_funct(const char* name, void (*fn)(void*, long), void* arg, int uses_fp,
                 int reentrant, int comp_id);
/// hal_create_thread: returns the thread id (> 0).
int thread_new(const char* name, unsigned long period, int uses_fp);
/// hal_thread_delete (threads stopped).
int thread_delete(const char* name);
/// hal_add_funct_to_thread: publishes a new call list.
int add_funct(const char* funct, const char* thread, int position);
/// hal_del_funct_from_thread: publishes a new call list and waits out the old one.
int del_funct(const char* funct, const char* thread);
/// Takes 'f' out of every thread's list and waits until no cycle can still be calling it.
void remove_funct_from_threads(Funct& f);
/// Runs one period of 't': its functions in order, timing each (the realtime path).
void run_cycle(Thread& t);
/// The thread whose cycle the calling OS thread is running, or nullptr.
const Thread* cycle_thread();
/// hal_start_threads: one OS thread per HAL thread.
int start_threads();
/// hal_stop_threads: joins them.
int stop_threads();
/// Runs 'ticks' base periods in the caller (threads stopped).
int step_ticks(std::uint64_t ticks);
/// Releases every shared-memory block (reset only).
void shmem_clear();

}  // namespace firtp::hal_shim::detail
