// interpreter_show.cpp - 'show': tables of components, pins, params, signals, functions, threads.
#include <fnmatch.h>

#include <cstdio>
#include <ostream>

#include "firtp/hal_shim/interpreter.hpp"

namespace firtp::hal_shim {

namespace {

/// halcmd matching: a glob when the pattern has * ? or [, else a name prefix.
bool matches(const std::string& pattern, const std::string& name) {
  if (pattern.empty()) return true;
  if (pattern.find_first_of("*?[") != std::string::npos)
    return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
  return name.compare(0, pattern.size(), pattern) == 0;
}

const char* dir_text(PinDir d) {
  switch (d) {
    case PinDir::In: return "IN";
    case PinDir::Out: return "OUT";
    case PinDir::IO: return "I/O";
  }
  return "?";
}

const char* arrow(PinDir d) {
  switch (d) {
    case PinDir::In: return "<==";
    case PinDir::Out: return "==>";
    case PinDir::IO: return "<=>";
  }
  return "";
}

/// printf into a std::string.
template <class... A>
std::string fmt(const char* f, A... a) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

}  // namespace

Status Interpreter::cmd_show(const Words& w) {
  const std::string what = w.size() > 1 ? w[1] : "all";
  const std::string pattern = w.size() > 2 ? w[2] : "";
  if (w.size() > 3) return Status::error(-EINVAL, "usage: show [WHAT] [PATTERN]");
  const bool all = what == "all";
  bool known = all;
  if (all || what == "comp") show_comps(pattern), known = true;
  if (all || what == "pin") show_pins(pattern), known = true;
  if (all || what == "param" || what == "parameter") show_params(pattern), known = true;
  if (all || what == "sig" || what == "signal") show_signals(pattern), known = true;
  if (all || what == "funct" || what == "function") show_functs(pattern), known = true;
  if (all || what == "thread") show_threads(pattern), known = true;
  out_ << std::flush;
  if (!known)
    return Status::error(-EINVAL, "show: unknown item '" + what +
                                      "' (comp, pin, param, sig, funct, thread or all)");
  return {};
}

void Interpreter::show_comps(const std::string& pattern) {
  out_ << "Loaded HAL Components:\n" << fmt("%4s  %-5s  %-16s  %s\n", "ID", "Ready", "Module", "Name");
  for (const auto& c : components())
    if (matches(pattern, c.name))
      out_ << fmt("%4d  %-5s  %-16s  %s\n", c.id, c.ready ? "yes" : "no", c.module.c_str(),
                  c.name.c_str());
  out_ << "\n";
}

void Interpreter::show_pins(const std::string& pattern) {
  out_ << "Component Pins:\n"
       << fmt("%-12s %-5s %-4s %20s  %s\n", "Owner", "Type", "Dir", "Value", "Name");
  for (const auto& p : pins()) {
    if (!matches(pattern, p.name)) continue;
    out_ << fmt("%-12s %-5s %-4s %20s  %s", p.owner.c_str(), type_name(p.type), dir_text(p.dir),
                format_value(p.value).c_str(), p.name.c_str());
    if (!p.signal.empty()) out_ << " " << arrow(p.dir) << " " << p.signal;
    out_ << "\n";
  }
  out_ << "\n";
}

void Interpreter::show_params(const std::string& pattern) {
  out_ << "Parameters:\n" << fmt("%-12s %-5s %-3s %20s  %s\n", "Owner", "Type", "Dir", "Value", "Name");
  for (const auto& p : params())
    if (matches(pattern, p.name))
      out_ << fmt("%-12s %-5s %-3s %20s  %s\n", p.owner.empty() ? "(thread)" : p.owner.c_str(),
                  type_name(p.type), p.dir == ParamDir::RO ? "RO" : "RW",
                  format_value(p.value).c_str(), p.name.c_str());
  out_ << "\n";
}

void Interpreter::show_signals(const std::string& pattern) {
  out_ << "Signals:\n" << fmt("%-5s %20s  %s\n", "Type", "Value", "Name     (linked to)");
  for (const auto& s : signals()) {
    if (!matches(pattern, s.name)) continue;
    out_ << fmt("%-5s %20s  %s\n", type_name(s.type), format_value(s.value).c_str(), s.name.c_str());
    if (!s.writer.empty()) out_ << fmt("%28s <== %s\n", "", s.writer.c_str());
    for (const auto& p : s.bidirs) out_ << fmt("%28s <=> %s\n", "", p.c_str());
    for (const auto& p : s.readers) out_ << fmt("%28s ==> %s\n", "", p.c_str());
  }
  out_ << "\n";
}

void Interpreter::show_functs(const std::string& pattern) {
  out_ << "Exported Functions:\n"
       << fmt("%-12s %5s %-3s %10s %10s  %s\n", "Owner", "Users", "FP", "Time(ns)", "Tmax(ns)", "Name");
  for (const auto& f : functs())
    if (matches(pattern, f.name))
      out_ << fmt("%-12s %5d %-3s %10d %10d  %s\n", f.owner.c_str(), f.users,
                  f.uses_fp ? "YES" : "NO", static_cast<int>(f.time_ns),
                  static_cast<int>(f.tmax_ns), f.name.c_str());
  out_ << "\n";
}

void Interpreter::show_threads(const std::string& pattern) {
  out_ << "Realtime Threads:\n"
       << fmt("%12s %-3s %12s %9s %10s %10s  %s\n", "Period(ns)", "FP", "Cycles", "Overruns",
              "Time(ns)", "Tmax(ns)", "Name");
  for (const auto& t : threads()) {
    if (!matches(pattern, t.name)) continue;
    out_ << fmt("%12ld %-3s %12llu %9llu %10d %10d  %s\n", t.period_ns, t.uses_fp ? "YES" : "NO",
                static_cast<unsigned long long>(t.cycles),
                static_cast<unsigned long long>(t.overruns), static_cast<int>(t.time_ns),
                static_cast<int>(t.tmax_ns), t.name.c_str());
    for (std::size_t i = 0; i < t.functs.size(); ++i)
      out_ << fmt("%16zu %s\n", i + 1, t.functs[i].c_str());
  }
  out_ << "\n";
}

}  // namespace firtp::hal_shim
