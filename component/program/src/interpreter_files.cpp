#include "interpreter_files.hpp"

#include "tooldata.hpp"

#include <firtp/ini.hpp>
#include <firtp/text_cat.hpp>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <unistd.h>

namespace firtp::gcode {
namespace {

// Without [EMCIO]TOOL_TABLE, tools T1..T999 exist with zero length and diameter (pocket = number),
// so CAM programs' tool changes and G43 read; their offsets are then zero.
constexpr int default_tools = 999;

std::filesystem::path make_temporary_directory() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = cat(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp", "/firtp-rs274.XXXXXX");
    if (::mkdtemp(pattern.data()) == nullptr)
        throw std::runtime_error(cat("cannot make a temporary directory ", pattern, ": ", std::strerror(errno)));
    return pattern;
}

// libtooldata keeps the tool table in a shared file it names $HOME/.tool.mmap and truncates: that
// is a running LinuxCNC's live table. Ours is made with HOME pointing at a directory of our own,
// then unlinked (the mapping stays): nobody else's table is touched.
void create_tool_table_once() {
    static std::once_flag once;
    std::call_once(once, [] {
        const TemporaryDirectory home;
        const char* old = std::getenv("HOME");
        const std::string saved = old != nullptr ? old : "";
        ::setenv("HOME", home.path().c_str(), 1);
        tool_mmap_creator(nullptr, 0);
        if (old != nullptr) ::setenv("HOME", saved.c_str(), 1);
        else ::unsetenv("HOME");
    });
}

}  // namespace

TemporaryDirectory::TemporaryDirectory() : path_(make_temporary_directory()) {}

TemporaryDirectory::~TemporaryDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
}

InterpreterFiles::InterpreterFiles(const MachineConfig& machine) : parameter_file_(dir_.path() / "firtp.var") {
    const std::string ini = machine.ini_file.string();
    std::error_code ec;
    if (!machine.parameter_file.empty() && std::filesystem::exists(machine.parameter_file, ec)) {
        if (!std::filesystem::copy_file(machine.parameter_file, parameter_file_, ec))
            throw ConfigError(cat(ini, ":0: [RS274NGC]PARAMETER_FILE ", machine.parameter_file.string(),
                                  ": cannot be read (", ec.message(), ")"));
    } else {
        std::ofstream{parameter_file_};  // LinuxCNC starts from an absent one the same way
    }

    create_tool_table_once();
    std::filesystem::path table = machine.tool_table;
    if (table.empty()) {
        table = dir_.path() / "firtp.tbl";
        std::ofstream out(table);
        for (int tool = 1; tool <= default_tools; ++tool) out << 'T' << tool << " P" << tool << " Z0 D0\n";
    }
    if (tooldata_load(table.c_str(), nullptr) != 0)
        throw ConfigError(cat(ini, ":0: [EMCIO]TOOL_TABLE ", table.string(), ": cannot be read"));
}

}  // namespace firtp::gcode
