// module_loader.cpp - loadrt/unloadrt: dlopen a component, set its RTAPI_MP_* parameters through
// the rtapi_info_* symbols, call rtapi_app_main/rtapi_app_exit; plus the built-in 'threads'.
#include <dlfcn.h>
#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "firtp/hal_shim/runtime.hpp"
#include "state.hpp"

namespace firtp::hal_shim {

using namespace detail;

namespace {

bool is_file(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

/// Splits "a:b:c" (empty parts dropped).
std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string part;
  for (char c : text) {
    if (c == sep) {
      if (!part.empty()) out.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  if (!part.empty()) out.push_back(part);
  return out;
}

/// Module name of a path: basename without ".so".
std::string module_name(const std::string& path) {
  std::string base = path.substr(path.find_last_of('/') + 1);
  if (base.size() > 3 && base.compare(base.size() - 3, 3, ".so") == 0) base.resize(base.size() - 3);
  return base;
}

/// Finds NAME.so: a path as given, else in dirs, $FIRTP_HAL_MODULE_PATH, ".".
Status resolve(const std::string& arg, const std::vector<std::string>& dirs, std::string& path) {
  if (arg.find('/') != std::string::npos) {
    if (!is_file(arg)) return Status::error(-ENOENT, "loadrt " + arg + ": no such file");
    path = arg;
    return {};
  }
  std::vector<std::string> search = dirs;
  if (const char* env = std::getenv("FIRTP_HAL_MODULE_PATH"))
    for (auto& d : split(env, ':')) search.push_back(d);
  search.emplace_back(".");
  const std::string file = module_name(arg) + ".so";
  std::string tried;
  for (auto& d : search) {
    if (is_file(d + "/" + file)) {
      path = d + "/" + file;
      return {};
    }
    tried += (tried.empty() ? "" : ":") + d;
  }
  return Status::error(-ENOENT, "loadrt " + arg + ": " + file + " not found (searched " + tried +
                                    "; add -L DIR or FIRTP_HAL_MODULE_PATH)");
}

/// Parses an int/long module parameter value.
bool parse_long(const std::string& text, long& out) {
  char* end = nullptr;
  errno = 0;
  out = std::strtol(text.c_str(), &end, 0);
  return !text.empty() && *end == '\0' && errno == 0;
}

/// Stores one element of kind 'kind' ('i', 'l', 's') at index 'idx' of the variable at 'var'.
Status store_item(Module& m, const std::string& pname, char kind, void* var, int idx,
                  const std::string& text) {
  long v = 0;
  switch (kind) {
    case 'i':
      if (!parse_long(text, v) || v < INT_MIN || v > INT_MAX)
        return Status::error(-EINVAL, "loadrt " + m.name + ": " + pname + "='" + text +
                                          "' is not an int");
      m.saved.push_back({&static_cast<int*>(var)[idx], 'i', static_cast<int*>(var)[idx], nullptr});
      static_cast<int*>(var)[idx] = static_cast<int>(v);
      return {};
    case 'l':
      if (!parse_long(text, v))
        return Status::error(-EINVAL, "loadrt " + m.name + ": " + pname + "='" + text +
                                          "' is not a long");
      m.saved.push_back({&static_cast<long*>(var)[idx], 'l', static_cast<long*>(var)[idx], nullptr});
      static_cast<long*>(var)[idx] = v;
      return {};
    case 's': {
      char* copy = strdup(text.c_str());
      m.owned_strings.push_back(copy);
      m.saved.push_back({&static_cast<char**>(var)[idx], 's', 0, static_cast<char**>(var)[idx]});
      static_cast<char**>(var)[idx] = copy;
      return {};
    }
    default:
      return Status::error(-EINVAL, "loadrt " + m.name + ": parameter " + pname +
                                        " has unknown type '" + std::string(1, kind) + "'");
  }
}

/// Sets module parameter "name=value" through the rtapi_info_{address,type,size}_NAME symbols.
Status set_module_param(Module& m, const std::string& arg) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0)
    return Status::error(-EINVAL, "loadrt " + m.name + ": '" + arg + "' is not name=value");
  const std::string pname = arg.substr(0, eq);
  std::string value = arg.substr(eq + 1);
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
    value = value.substr(1, value.size() - 2);
  auto* address = static_cast<void**>(dlsym(m.handle, ("rtapi_info_address_" + pname).c_str()));
  auto* type = static_cast<const char**>(dlsym(m.handle, ("rtapi_info_type_" + pname).c_str()));
  if (address == nullptr || type == nullptr || *type == nullptr || **type == '\0')
    return Status::error(-EINVAL, "loadrt " + m.name + ": unknown parameter '" + pname +
                                      "' (not declared with RTAPI_MP_*)");
  char kind = (*type)[std::strlen(*type) - 1];  // "i", "l", "s" (older: "1-8i")
  const auto* size = static_cast<const int*>(dlsym(m.handle, ("rtapi_info_size_" + pname).c_str()));
  if (size == nullptr) return store_item(m, pname, kind, *address, 0, value);
  std::vector<std::string> items;
  std::string cur;
  for (char c : value) {
    if (c == ',') {
      items.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  items.push_back(cur);
  if (static_cast<long>(items.size()) > *size)
    return Status::error(-EINVAL, "loadrt " + m.name + ": " + pname + " takes at most " +
                                      std::to_string(*size) + " values");
  for (std::size_t i = 0; i < items.size(); ++i)
    if (Status st = store_item(m, pname, kind, *address, static_cast<int>(i), items[i]); !st.ok())
      return st;
  return {};
}

/// Built-in 'threads': name1..3=NAME period1..3=NS fp1..3=0|1.
Status load_threads(State& s, const std::vector<std::string>& args) {
  std::string names[3], periods[3], fps[3] = {"1", "1", "1"};
  for (const auto& a : args) {
    const auto eq = a.find('=');
    const std::string key = eq == std::string::npos ? a : a.substr(0, eq);
    const std::string val = eq == std::string::npos ? "" : a.substr(eq + 1);
    bool known = false;
    for (int i = 0; i < 3; ++i) {
      const std::string n = std::to_string(i + 1);
      if (key == "name" + n) names[i] = val, known = true;
      if (key == "period" + n) periods[i] = val, known = true;
      if (key == "fp" + n) fps[i] = val, known = true;
    }
    if (!known || eq == std::string::npos)
      return Status::error(-EINVAL, "loadrt threads: unknown argument '" + a +
                                        "' (use nameN=, periodN=, fpN= with N 1..3)");
  }
  Module m;
  m.name = "threads";
  for (int i = 0; i < 3; ++i) {
    if (names[i].empty()) continue;
    long period = 0;
    if (!parse_long(periods[i], period) || period <= 0)
      return Status::error(-EINVAL, "loadrt threads: period" + std::to_string(i + 1) + "='" +
                                        periods[i] + "' is not a positive number of ns");
    if (Status st = new_thread(names[i], period, fps[i] != "0"); !st.ok()) {
      for (auto& t : m.threads) thread_delete(t.c_str());
      return st;
    }
    m.threads.push_back(names[i]);
  }
  s.modules.push_back(std::move(m));
  return {};
}

/// Ids of the components a module created.
std::vector<int> comps_of(State& s, const std::string& module) {
  std::vector<int> ids;
  for (auto& [id, c] : s.comps)
    if (c.module == module) ids.push_back(id);
  return ids;
}

/// Frees what a failed or unloaded module leaves: components, strings, the handle.
void discard(State& s, Module& m) {
  for (int id : comps_of(s, m.name)) comp_exit(id);
  for (auto it = m.saved.rbegin(); it != m.saved.rend(); ++it) {  // as before loadrt, last set first
    if (it->kind == 'i') *static_cast<int*>(it->address) = static_cast<int>(it->integer);
    if (it->kind == 'l') *static_cast<long*>(it->address) = it->integer;
    if (it->kind == 's') *static_cast<char**>(it->address) = it->string;
  }
  m.saved.clear();
  if (m.handle != nullptr) dlclose(m.handle);
  for (char* p : m.owned_strings) std::free(p);
  m.owned_strings.clear();
  m.handle = nullptr;
}

}  // namespace

Status load_module(const std::string& name_or_path, const std::vector<std::string>& args,
                   const std::vector<std::string>& search_dirs) {
  State& s = state();
  Lock lock(s.mu);
  const std::string name = module_name(name_or_path);
  for (auto& m : s.modules)
    if (m.name == name) return Status::error(-EEXIST, "module '" + name + "' is already loaded");
  if (name_or_path == "threads") return load_threads(s, args);
  std::string path;
  if (Status st = resolve(name_or_path, search_dirs, path); !st.ok()) return st;
  Module m;
  m.name = name;
  m.path = path;
  m.handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (m.handle == nullptr) return Status::error(-ENOEXEC, "loadrt " + name + ": " + dlerror());
  for (const auto& a : args) {
    if (Status st = set_module_param(m, a); !st.ok()) {
      discard(s, m);
      return st;
    }
  }
  using AppMain = int (*)();
  auto app_main = reinterpret_cast<AppMain>(dlsym(m.handle, "rtapi_app_main"));
  if (app_main == nullptr) {
    discard(s, m);
    return Status::error(-ENOEXEC, "loadrt " + name +
                                       ": no rtapi_app_main symbol (C++: declare it extern \"C\")");
  }
  clear_error();
  s.loading_module = name;
  const int rc = app_main();
  s.loading_module.clear();
  if (rc < 0) {
    std::string why = last_error_text();
    discard(s, m);
    return Status::error(rc, "loadrt " + name + ": rtapi_app_main failed: " +
                                 std::strerror(-rc) + (why.empty() ? "" : " (" + why + ")"));
  }
  for (int id : comps_of(s, name))
    if (!find_comp(id)->ready)
      rtapi_print_msg(RTAPI_MSG_WARN, "HAL: WARNING: component '%s' did not call hal_ready\n",
                      find_comp(id)->name.c_str());
  s.modules.push_back(std::move(m));
  return {};
}

Status unload_module(const std::string& name) {
  State& s = state();
  Lock lock(s.mu);
  if (name == "all") {
    detail::stop_threads();
    Status first;
    while (!s.modules.empty()) {
      Status st = unload_module(s.modules.back().name);
      if (!st.ok()) {
        if (first.ok()) first = st;
        s.modules.pop_back();
      }
    }
    return first;
  }
  auto it = s.modules.begin();
  while (it != s.modules.end() && it->name != name) ++it;
  if (it == s.modules.end()) return Status::error(-EINVAL, "module '" + name + "' is not loaded");
  if (it->handle == nullptr) {  // built-in threads
    if (s.running) return Status::error(-EBUSY, "unloadrt threads: stop threads first");
    for (auto& t : it->threads) thread_delete(t.c_str());
    s.modules.erase(it);
    return {};
  }
  for (int id : comps_of(s, name))  // out of the threads before its code can go away
    for (auto& [fname, f] : s.functs)
      if (f->owner == id) remove_funct_from_threads(*f);
  using AppExit = void (*)();
  if (auto app_exit = reinterpret_cast<AppExit>(dlsym(it->handle, "rtapi_app_exit"))) app_exit();
  Module m = std::move(*it);
  s.modules.erase(it);
  discard(s, m);
  return {};
}

std::vector<std::string> loaded_modules() {
  State& s = state();
  Lock lock(s.mu);
  std::vector<std::string> out;
  for (auto& m : s.modules) out.push_back(m.name);
  return out;
}

}  // namespace firtp::hal_shim
