// Files LinuxCNC's interpreter needs beside the program, in a temporary directory: a copy of the
// machine's parameter file (the interpreter writes it back at the end; the user's stays as it was)
// or an empty one, and the tool table ([EMCIO]TOOL_TABLE, else T1..T999 of zero length and
// diameter) loaded into libtooldata's table. Internal to the reader.
#pragma once

#include <firtp/machine.hpp>

#include <filesystem>
#include <string>

namespace firtp::gcode {

// mkdtemp under $TMPDIR (else /tmp), removed with its contents by the destructor.
class TemporaryDirectory {
public:
    TemporaryDirectory();
    ~TemporaryDirectory();
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

class InterpreterFiles {
public:
    // Throws ConfigError naming the INI's file when its parameter file or tool table cannot be read.
    explicit InterpreterFiles(const MachineConfig& machine);
    std::string parameter_file() const { return parameter_file_.string(); }

private:
    TemporaryDirectory dir_;
    std::filesystem::path parameter_file_;
};

}  // namespace firtp::gcode
