// Runs the built firtp binary as a subprocess and gives what it printed; temporary directories.
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace firtp::cli_test {

struct Outcome {
    int exit_code = -1;  // -1 when killed by a signal
    std::string out;     // stdout
    std::string err;     // stderr
};

// Runs FIRTP_BIN with `args`; `path_env` replaces PATH when given.
Outcome run_firtp(const std::vector<std::string>& args, const std::optional<std::string>& path_env = std::nullopt);

// A fresh directory, removed with everything in it at the end of the test.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    std::set<std::string> names() const;  // every entry, hidden ones too

private:
    std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& path);
void write_file(const std::filesystem::path& path, const std::string& text);
std::filesystem::path example(const std::string& name);  // examples/<name> of the source tree
bool gnuplot_on_path();  // plots are tested only where gnuplot is installed

}  // namespace firtp::cli_test
