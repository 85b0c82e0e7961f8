// main.cpp - firtp-hal: runs HAL components without LinuxCNC, from a halcmd-style script.
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include "firtp/hal_shim/interpreter.hpp"
#include "firtp/version.hpp"
#include "rtapi.h"

namespace {

const char* const kUsage =
    "usage: firtp-hal [options] [-f FILE | FILE]\n"
    "Reads halcmd-style commands from FILE (or standard input) and runs them.\n"
    "  -f FILE        command file ('-' = standard input)\n"
    "  --version      print the version\n"
    "  -n TICKS       at 'start', run TICKS base periods (with --no-realtime) or wait for them\n"
    "  --no-realtime  virtual time: 'start' runs nothing by itself; 'step N', 'sleep' and\n"
    "                 'wait MS' run whole periods at once, deterministic and fast\n"
    "  -L DIR         look for loadrt modules in DIR (also: $FIRTP_HAL_MODULE_PATH, then\n"
    "                 ../lib/firtp next to this program when installed)\n"
    "  -k             keep going after an error (still exits 1)\n"
    "  -v             more messages (-v info, -vv debug)\n"
    "  --rt-prio N    run threads SCHED_FIFO at priority N (default: normal scheduling)\n"
    "  -h, --help     this text; 'help' in a script lists the commands\n"
    "Errors print as FILE:LINE: message; the exit status is 0 when every command succeeded.\n";

extern "C" void on_signal(int) { firtp::hal_shim::Interpreter::request_stop(); }

/// Parses a non-negative integer option value; exits with usage on error.
unsigned long long number(const char* opt, const char* text) {
  char* end = nullptr;
  unsigned long long v = std::strtoull(text, &end, 0);
  if (*text == '\0' || *text == '-' || *end != '\0') {
    std::cerr << "firtp-hal: " << opt << " needs a number, not '" << text << "'\n" << kUsage;
    std::exit(2);
  }
  return v;
}

/// Installed (PREFIX/bin/firtp-hal), loadrt also looks in PREFIX/lib/firtp, after -L and
/// $FIRTP_HAL_MODULE_PATH: appended to the latter.
void add_installed_module_dir() {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return;
  std::string dir(self, static_cast<std::size_t>(n));
  dir = dir.substr(0, dir.find_last_of('/'));                       // PREFIX/bin
  dir = dir.substr(0, dir.find_last_of('/')) + "/lib/firtp";        // PREFIX/lib/firtp
  if (access((dir + "/firtp.so").c_str(), R_OK) != 0) return;
  const char* path = std::getenv("FIRTP_HAL_MODULE_PATH");
  setenv("FIRTP_HAL_MODULE_PATH", (path && *path ? std::string(path) + ":" + dir : dir).c_str(), 1);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace firtp::hal_shim;
  InterpreterOptions opt;
  std::string file;
  int verbose = 0;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) {
        std::cerr << "firtp-hal: " << name << " needs a value\n" << kUsage;
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--version") {
      std::cout << "firtp-hal " << firtp::version << "\n";
      return 0;
    } else if (a == "-f") {
      file = value("-f");
    } else if (a == "-n") {
      opt.start_ticks = number("-n", value("-n"));
    } else if (a == "--no-realtime") {
      opt.realtime = false;
    } else if (a == "-L") {
      opt.module_dirs.emplace_back(value("-L"));
    } else if (a == "-k") {
      opt.keep_going = true;
    } else if (a == "-v" || a == "-vv") {
      verbose += a == "-v" ? 1 : 2;
    } else if (a == "--rt-prio") {
      set_rt_priority(static_cast<int>(number("--rt-prio", value("--rt-prio"))));
    } else if (!a.empty() && a[0] != '-' && file.empty()) {
      file = a;
    } else {
      std::cerr << "firtp-hal: unknown option '" << a << "'\n" << kUsage;
      return 2;
    }
  }
  add_installed_module_dir();
  rtapi_set_msg_level(verbose >= 2 ? RTAPI_MSG_DBG : verbose == 1 ? RTAPI_MSG_INFO : RTAPI_MSG_ERR);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  Interpreter interp(opt, std::cout, std::cerr);
  int errors = 0;
  if (file.empty() || file == "-") {
    errors = interp.run(std::cin, "<stdin>", isatty(STDIN_FILENO) != 0);
  } else {
    std::ifstream in(file);
    if (!in) {
      std::cerr << "firtp-hal: cannot open '" << file << "': " << std::strerror(errno) << "\n";
      return 2;
    }
    errors = interp.run(in, file);
  }
  interp.shutdown();
  if (Interpreter::stop_requested()) return 130;
  return errors == 0 ? 0 : 1;
}
