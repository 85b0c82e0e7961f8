// interpreter.cpp - firtp-hal commands: parsing a line and carrying it out.
#include "firtp/hal_shim/interpreter.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <thread>

namespace firtp::hal_shim {

namespace {

std::atomic<bool> g_stop{false};

const char* const kHelp =
    "loadrt MODULE [name=value ...]   load a component (.so path or NAME); 'threads' is built in:\n"
    "                                 loadrt threads name1=servo period1=1000000 [fp1=1] ...\n"
    "unloadrt MODULE|all              unload a component\n"
    "newthread NAME PERIOD_NS [fp|nofp]   create a thread (first = base period)\n"
    "delthread NAME                   delete a thread\n"
    "newsig SIGNAL bit|float|s32|u32  create a signal\n"
    "delsig SIGNAL                    delete a signal\n"
    "net SIGNAL [<=|=>|<=>] PIN ...   link pins to a signal (created with the first pin's type)\n"
    "linkps PIN SIGNAL / linksp SIGNAL PIN / unlinkp PIN\n"
    "setp PIN|PARAM VALUE             set a param or an unlinked input pin (also: NAME = VALUE)\n"
    "sets SIGNAL VALUE                set a signal that has no writer\n"
    "getp PIN|PARAM / gets SIGNAL     print a value\n"
    "ptype PIN|PARAM / stype SIGNAL   print a type\n"
    "addf FUNCT THREAD [POSITION]     add a function to a thread (1 first, -1 last)\n"
    "delf FUNCT THREAD                remove it\n"
    "start / stop                     start or stop the threads\n"
    "step [N]                         run N base periods now, without the clock (threads stopped)\n"
    "wait [MS] / sleep SECONDS        let time pass (virtual time: step that long if started);\n"
    "                                 'wait' alone: until SIGINT/SIGTERM\n"
    "loadusr -w sleep SECONDS         the same, as LinuxCNC's HAL files write it (halrun runs them too)\n"
    "show [comp|pin|param|sig|funct|thread|all] [PATTERN]\n"
    "echo TEXT / help / exit\n";

bool parse_int64(const std::string& text, long long& out) {
  char* end = nullptr;
  errno = 0;
  out = std::strtoll(text.c_str(), &end, 0);
  return !text.empty() && *end == '\0' && errno == 0;
}

bool parse_double(const std::string& text, double& out) {
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(out);
}

Status usage(const std::string& text) { return Status::error(-EINVAL, "usage: " + text); }

}  // namespace

Interpreter::Interpreter(InterpreterOptions options, std::ostream& out, std::ostream& err)
    : options_(std::move(options)), out_(out), err_(err) {}

void Interpreter::request_stop() { g_stop.store(true); }

bool Interpreter::stop_requested() { return g_stop.load(); }

bool Interpreter::tokenize(const std::string& line, std::vector<std::string>& words) {
  words.clear();
  std::string cur;
  bool in_word = false, quoted = false;
  for (char c : line) {
    if (quoted) {
      if (c == '"') quoted = false;
      else cur += c;
      continue;
    }
    if (c == '"') {
      quoted = true;
      in_word = true;
    } else if (c == '#' && !in_word) {
      break;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      if (in_word) words.push_back(cur);
      cur.clear();
      in_word = false;
    } else {
      cur += c;
      in_word = true;
    }
  }
  if (quoted) return false;
  if (in_word) words.push_back(cur);
  return true;
}

Status Interpreter::execute(const std::string& line) {
  Words w;
  if (!tokenize(line, w)) return Status::error(-EINVAL, "unclosed quote");
  if (w.empty()) return {};
  return dispatch(w);
}

int Interpreter::run(std::istream& in, const std::string& source, bool prompt) {
  int errors = 0;
  std::string line, pending;
  int lineno = 0, first = 0;
  while (!finished_ && !stop_requested()) {
    if (prompt) out_ << "firtp-hal> " << std::flush;
    if (!std::getline(in, line)) break;
    ++lineno;
    if (pending.empty()) first = lineno;
    if (!line.empty() && line.back() == '\\') {  // continuation
      pending += line.substr(0, line.size() - 1) + " ";
      continue;
    }
    pending += line;
    Status st = execute(pending);
    pending.clear();
    if (!st.ok()) {
      ++errors;
      err_ << source << ":" << first << ": " << st.message << "\n" << std::flush;
      if (!options_.keep_going && !prompt) break;
    }
  }
  if (stop_requested()) finished_ = true;
  return errors;
}

void Interpreter::shutdown() {
  stop_threads();
  started_ = false;
  unload_module("all");
}

Status Interpreter::dispatch(const Words& w) {
  const std::string& cmd = w[0];
  const auto n = w.size();
  if (n == 3 && w[1] == "=") return set_value(w[0], w[2]);
  if (cmd == "loadrt") {
    if (n < 2) return usage("loadrt MODULE [name=value ...]");
    return load_module(w[1], Words(w.begin() + 2, w.end()), options_.module_dirs);
  }
  if (cmd == "unloadrt") {
    if (n != 2) return usage("unloadrt MODULE|all");
    if (w[1] == "all") started_ = false;
    return unload_module(w[1]);
  }
  if (cmd == "newsig") {
    Type t;
    if (n != 3) return usage("newsig SIGNAL bit|float|s32|u32");
    if (!parse_type(w[2], t))
      return Status::error(-EINVAL, "newsig " + w[1] + ": unknown type '" + w[2] +
                                        "' (bit, float, s32 or u32)");
    return new_signal(w[1], t);
  }
  if (cmd == "delsig") return n == 2 ? delete_signal(w[1]) : usage("delsig SIGNAL");
  if (cmd == "net") {
    if (n < 3) return usage("net SIGNAL [<=|=>|<=>] PIN ...");
    return net(w[1], Words(w.begin() + 2, w.end()));
  }
  if (cmd == "linkps") {
    if (n == 4 && (w[2] == "=>" || w[2] == "<=" || w[2] == "<=>")) return link(w[1], w[3]);
    return n == 3 ? link(w[1], w[2]) : usage("linkps PIN SIGNAL");
  }
  if (cmd == "linksp") {
    if (n == 4 && (w[2] == "=>" || w[2] == "<=" || w[2] == "<=>")) return link(w[3], w[1]);
    return n == 3 ? link(w[2], w[1]) : usage("linksp SIGNAL PIN");
  }
  if (cmd == "unlinkp") return n == 2 ? unlink(w[1]) : usage("unlinkp PIN");
  if (cmd == "setp") return n == 3 ? set_value(w[1], w[2]) : usage("setp PIN|PARAM VALUE");
  if (cmd == "sets") return n == 3 ? set_signal(w[1], w[2]) : usage("sets SIGNAL VALUE");
  if (cmd == "getp" || cmd == "gets" || cmd == "ptype" || cmd == "stype") {
    if (n != 2) return usage(cmd + " NAME");
    const bool signal = cmd == "gets" || cmd == "stype";
    const bool want_type = cmd == "ptype" || cmd == "stype";
    Value v;
    if (Status st = signal ? get_signal(w[1], v) : get_value(w[1], v); !st.ok()) return st;
    out_ << (want_type ? std::string(type_name(v.type)) : format_value(v)) << "\n" << std::flush;
    return {};
  }
  if (cmd == "newthread") {
    long long period = 0;
    if (n < 3 || n > 4 || !parse_int64(w[2], period) || period <= 0 ||
        (n == 4 && w[3] != "fp" && w[3] != "nofp"))
      return usage("newthread NAME PERIOD_NS [fp|nofp]");
    return new_thread(w[1], static_cast<long>(period), n == 3 || w[3] == "fp");
  }
  if (cmd == "delthread") return n == 2 ? delete_thread(w[1]) : usage("delthread NAME");
  if (cmd == "addf") {
    long long pos = -1;
    if (n < 3 || n > 4 || (n == 4 && !parse_int64(w[3], pos)))
      return usage("addf FUNCT THREAD [POSITION]");
    return add_funct(w[1], w[2], static_cast<int>(pos));
  }
  if (cmd == "delf") return n == 3 ? del_funct(w[1], w[2]) : usage("delf FUNCT THREAD");
  if (cmd == "start") return n == 1 ? cmd_start() : usage("start");
  if (cmd == "stop") return n == 1 ? cmd_stop() : usage("stop");
  if (cmd == "step") {
    long long ticks = 1;
    if (n > 2 || (n == 2 && (!parse_int64(w[1], ticks) || ticks < 0))) return usage("step [N]");
    if (options_.realtime && threads_running())
      return Status::error(-EBUSY, "step: threads are running in real time ('stop' first)");
    return step(static_cast<std::uint64_t>(ticks));
  }
  if (cmd == "wait") {
    if (n == 1) return cmd_wait_forever();
    long long ms = 0;
    if (n != 2 || !parse_int64(w[1], ms) || ms < 0) return usage("wait [MS]");
    return cmd_sleep_ns(ms * 1000000LL);
  }
  if (cmd == "sleep") {
    double sec = 0;
    if (n != 2 || !parse_double(w[1], sec) || sec < 0) return usage("sleep SECONDS");
    return cmd_sleep_ns(std::llround(sec * 1e9));
  }
  if (cmd == "show") return cmd_show(w);
  if (cmd == "echo") {
    for (std::size_t i = 1; i < n; ++i) out_ << (i > 1 ? " " : "") << w[i];
    out_ << "\n" << std::flush;
    return {};
  }
  if (cmd == "help") {
    out_ << kHelp << std::flush;
    return {};
  }
  if (cmd == "exit" || cmd == "quit") {
    finished_ = true;
    return {};
  }
  if (cmd == "loadusr" && n == 4 && w[1] == "-w" && w[2] == "sleep") {  // LinuxCNC's way to wait in a HAL file
    double sec = 0;
    if (!parse_double(w[3], sec) || sec < 0) return usage("loadusr -w sleep SECONDS");
    return cmd_sleep_ns(std::llround(sec * 1e9));
  }
  if (cmd == "loadusr" || cmd == "waitusr")
    return Status::error(-ENOSYS, cmd + " is not supported by firtp-hal (run the program beside it)");
  return Status::error(-EINVAL, "unknown command '" + cmd + "' (try 'help')");
}

Status Interpreter::cmd_start() {
  if (options_.realtime) {
    if (Status st = start_threads(); !st.ok()) return st;
    started_ = true;
    if (options_.start_ticks == 0) return {};
    auto all = threads();
    if (all.empty()) return {};
    std::string fastest = all.front().name;  // threads are created fastest first
    const std::uint64_t target = thread_cycles(fastest) + options_.start_ticks;
    while (thread_cycles(fastest) < target && !stop_requested())
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    return {};
  }
  started_ = true;
  return options_.start_ticks > 0 ? step(options_.start_ticks) : Status{};
}

Status Interpreter::cmd_stop() {
  started_ = false;
  return options_.realtime ? stop_threads() : Status{};
}

Status Interpreter::cmd_sleep_ns(long long ns) {
  if (!options_.realtime) {
    if (!started_) return {};
    const long base = base_period_ns();
    if (base <= 0) return {};
    return step(static_cast<std::uint64_t>((ns + base / 2) / base));
  }
  const auto end = std::chrono::steady_clock::now() + std::chrono::nanoseconds(ns);
  while (!stop_requested()) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= end) break;
    std::this_thread::sleep_for(std::min<std::chrono::nanoseconds>(end - now,
                                                                   std::chrono::milliseconds(50)));
  }
  return {};
}

Status Interpreter::cmd_wait_forever() {
  if (!options_.realtime)
    return Status::error(-EINVAL, "wait without a time needs real time (drop --no-realtime)");
  while (!stop_requested()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return {};
}

}  // namespace firtp::hal_shim
