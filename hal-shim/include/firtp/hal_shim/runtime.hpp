// firtp/hal_shim/runtime.hpp - C++ control side of the HAL shim: what halcmd does, as calls.
//
// Components use the C API (hal.h, rtapi.h); the runner (firtp-hal) and tests configure and run
// them through these functions.  All of them are for configuration time: they lock, allocate and
// may print; none is called from a thread's function list.  Independent of hal.h on purpose.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace firtp::hal_shim {

/// Value types (same numbers as hal_type_t).
enum class Type : int { Bit = 1, Float = 2, S32 = 3, U32 = 4 };
/// Pin directions (same numbers as hal_pin_dir_t).
enum class PinDir : int { In = 16, Out = 32, IO = 48 };
/// Parameter directions (same numbers as hal_param_dir_t).
enum class ParamDir : int { RO = 64, RW = 192 };

/// Outcome of a call: code 0 or a negative errno, with a message saying what went wrong.
struct Status {
  int code = 0;
  std::string message;
  /// True on success.
  [[nodiscard]] bool ok() const { return code == 0; }
  /// A failure with 'code' (negative errno) and 'message'.
  static Status error(int code, std::string message) { return {code, std::move(message)}; }
};

/// One HAL value with its type; only the member of that type is meaningful.
struct Value {
  Type type = Type::Float;
  bool b = false;
  std::int32_t s = 0;
  std::uint32_t u = 0;
  double f = 0.0;
  /// The value as a double whatever its type (bit: 0/1).
  [[nodiscard]] double as_double() const;
};

/// A pin as 'show pin' lists it.
struct PinInfo {
  std::string name, owner, signal;  // signal empty when unlinked
  Type type;
  PinDir dir;
  Value value;
};
/// A parameter as 'show param' lists it.
struct ParamInfo {
  std::string name, owner;
  Type type;
  ParamDir dir;
  Value value;
};
/// A signal and the pins linked to it.
struct SignalInfo {
  std::string name;
  Type type;
  Value value;
  std::string writer;                // the HAL_OUT pin, if any
  std::vector<std::string> readers;  // HAL_IN pins
  std::vector<std::string> bidirs;   // HAL_IO pins
};
/// An exported function.
struct FunctInfo {
  std::string name, owner;
  int users;  // threads that call it
  bool uses_fp, reentrant;
  std::int32_t time_ns, tmax_ns;  // last and longest run (the name.time/name.tmax params)
};
/// A thread and its call list.
struct ThreadInfo {
  std::string name;
  long period_ns;
  bool uses_fp;
  std::uint64_t cycles;    // periods run so far
  std::uint64_t overruns;  // periods that ended past the next deadline (realtime only)
  std::int32_t time_ns, tmax_ns;
  std::vector<std::string> functs;  // in call order
};
/// A component (hal_init).
struct CompInfo {
  int id;
  std::string name, module;  // module: loadrt name that created it ("" if none)
  bool ready;
};

// ---- values -----------------------------------------------------------------------------------

/// "bit", "float", "s32", "u32".
const char* type_name(Type type);
/// Parses a type name; false if unknown.
bool parse_type(const std::string& text, Type& out);
/// Parses text as a value of 'type' (bit: 1/0/TRUE/FALSE/true/false; ints: decimal or 0x..).
Status parse_value(Type type, const std::string& text, Value& out);
/// halcmd-style text: TRUE/FALSE, shortest round-trip float, decimal ints.
std::string format_value(const Value& value);

// ---- modules ----------------------------------------------------------------------------------

/// loadrt: dlopen a component (path, or NAME.so in search_dirs, $FIRTP_HAL_MODULE_PATH, ".")
/// with RTLD_NOW|RTLD_LOCAL, set "name=value" module parameters, call rtapi_app_main().
/// NAME "threads" is built in: name1=N period1=NS [fp1=0|1] ... name3/period3/fp3.
Status load_module(const std::string& name_or_path, const std::vector<std::string>& args,
                   const std::vector<std::string>& search_dirs = {});
/// unloadrt: remove the module's functions from threads, call rtapi_app_exit(), hal_exit() what
/// it left, dlclose.  "all" unloads every module, last loaded first.
Status unload_module(const std::string& name);
/// Names of the loaded modules, in load order.
std::vector<std::string> loaded_modules();

// ---- signals, pins, params -------------------------------------------------------------------

/// newsig.
Status new_signal(const std::string& name, Type type);
/// delsig.
Status delete_signal(const std::string& name);
/// linkps: link a pin to an existing signal.
Status link(const std::string& pin, const std::string& signal);
/// unlinkp.
Status unlink(const std::string& pin);
/// net SIGNAL [<=|=>|<=>] PIN ...: creates the signal (type of the first pin) when missing,
/// then links every pin; arrows are accepted and ignored.
Status net(const std::string& signal, const std::vector<std::string>& pins);
/// setp: a HAL_RW param, or an unlinked input (HAL_IN/HAL_IO) pin.
Status set_value(const std::string& name, const std::string& text);
/// sets: a signal without a writer pin.
Status set_signal(const std::string& name, const std::string& text);
/// getp: a param or a pin (params first, as halcmd).
Status get_value(const std::string& name, Value& out);
/// gets.
Status get_signal(const std::string& name, Value& out);

// ---- threads ----------------------------------------------------------------------------------

/// newthread (as 'loadrt threads'): the first thread sets the base period.
Status new_thread(const std::string& name, long period_ns, bool uses_fp = true);
/// delthread.
Status delete_thread(const std::string& name);
/// addf: position 1 = first, -1 = last.
Status add_funct(const std::string& funct, const std::string& thread, int position = -1);
/// delf.
Status del_funct(const std::string& funct, const std::string& thread);
/// start: one OS thread per HAL thread, clock_nanosleep on CLOCK_MONOTONIC absolute deadlines.
Status start_threads();
/// stop: returns once every thread finished its current cycle.
Status stop_threads();
/// True between start_threads() and stop_threads().
bool threads_running();
/// Runs 'ticks' base periods in the calling thread, no clock: a thread of period k*base runs
/// every k-th tick, fastest first.  Refused while threads run.
Status step(std::uint64_t ticks);
/// Base period in ns (0 before the first thread).
long base_period_ns();
/// Cycles run by 'thread' (0 if none).
std::uint64_t thread_cycles(const std::string& thread);
/// SCHED_FIFO priority for threads started later (0: normal scheduling, the default).
void set_rt_priority(int priority);

// ---- inspection ------------------------------------------------------------------------------

/// Components, by id.
std::vector<CompInfo> components();
/// Pins, by name, with their current values.
std::vector<PinInfo> pins();
/// Params, by name (thread params have no owner).
std::vector<ParamInfo> params();
/// Signals, by name, with their pins.
std::vector<SignalInfo> signals();
/// Functions, by name.
std::vector<FunctInfo> functs();
/// Threads, in creation order (fastest first).
std::vector<ThreadInfo> threads();
/// Bytes of HAL memory used and available.
std::size_t arena_used();
std::size_t arena_size();

/// Message of the last failed HAL call in this thread (C API included).
const std::string& last_error();

/// Stops threads, unloads every module, deletes signals and threads, exits leftover components
/// and rewinds the HAL memory: a fresh HAL (for tests).
void reset();

}  // namespace firtp::hal_shim
