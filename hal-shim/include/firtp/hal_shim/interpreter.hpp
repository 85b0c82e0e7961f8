// firtp/hal_shim/interpreter.hpp - the halcmd-style command language of firtp-hal.
//
// One command a line; '#' starts a comment, "..." groups words, a trailing '\' continues the
// line.  Commands: loadrt unloadrt newsig delsig net linkps linksp unlinkp setp sets getp gets
// ptype stype newthread delthread addf delf start stop step wait sleep show echo help exit.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "firtp/hal_shim/runtime.hpp"

namespace firtp::hal_shim {

struct InterpreterOptions {
  bool realtime = true;                   // false: virtual time, 'start' runs nothing by itself
  std::uint64_t start_ticks = 0;          // -n: base periods run (or awaited) at 'start'
  std::vector<std::string> module_dirs;   // -L: where loadrt looks for NAME.so
  bool keep_going = false;                // -k: go on after an error (still exit non-zero)
};

/// Executes firtp-hal commands against the process's HAL.
class Interpreter {
 public:
  /// Commands print results on 'out' and "source:line: message" errors on 'err'.
  Interpreter(InterpreterOptions options, std::ostream& out, std::ostream& err);

  /// Executes one line; blank lines and comments succeed.
  Status execute(const std::string& line);
  /// Executes every line of 'in' (named 'source' in messages); returns the number of errors.
  int run(std::istream& in, const std::string& source, bool prompt = false);
  /// True once 'exit' or 'quit' ran, or an interrupt was requested.
  [[nodiscard]] bool finished() const { return finished_; }
  /// Stops threads and unloads every module (last loaded first).
  void shutdown();

  /// Async-signal-safe: makes 'wait'/'sleep' return and run() stop after the current line.
  static void request_stop();
  /// True after request_stop().
  static bool stop_requested();

  /// Splits a line into words ("..." groups, # comments); false on an unclosed quote.
  static bool tokenize(const std::string& line, std::vector<std::string>& words);

 private:
  using Words = std::vector<std::string>;
  Status dispatch(const Words& w);
  Status cmd_start();
  Status cmd_stop();
  Status cmd_sleep_ns(long long ns);
  Status cmd_wait_forever();
  Status cmd_show(const Words& w);
  void show_comps(const std::string& pattern);
  void show_pins(const std::string& pattern);
  void show_params(const std::string& pattern);
  void show_signals(const std::string& pattern);
  void show_functs(const std::string& pattern);
  void show_threads(const std::string& pattern);

  InterpreterOptions options_;
  std::ostream& out_;
  std::ostream& err_;
  bool started_ = false;  // 'start' ran and 'stop' did not (either mode)
  bool finished_ = false;
};

}  // namespace firtp::hal_shim
