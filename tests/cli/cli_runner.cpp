#include "cli_runner.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace firtp::cli_test {
namespace {

std::vector<std::string> environment(const std::optional<std::string>& path_env) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
        if (!path_env || std::strncmp(*e, "PATH=", 5) != 0) env.emplace_back(*e);
    if (path_env) env.push_back("PATH=" + *path_env);
    return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (std::string& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

}  // namespace

Outcome run_firtp(const std::vector<std::string>& args, const std::optional<std::string>& path_env) {
    const TempDir capture;
    const std::string out_file = (capture / "stdout").string();
    const std::string err_file = (capture / "stderr").string();

    std::vector<std::string> argv{FIRTP_BIN};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<std::string> env = environment(path_env);
    std::vector<char*> argv_p = pointers(argv);
    std::vector<char*> env_p = pointers(env);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, FIRTP_BIN, &actions, nullptr, argv_p.data(), env_p.data());
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw std::runtime_error(std::string("cannot start " FIRTP_BIN ": ") + std::strerror(spawned));

    int status = 0;
    waitpid(pid, &status, 0);
    Outcome outcome;
    outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    outcome.out = read_file(out_file);
    outcome.err = read_file(err_file);
    return outcome;
}

TempDir::TempDir() {
    std::string name = (std::filesystem::temp_directory_path() / "firtp-cli-test-XXXXXX").string();
    if (!mkdtemp(name.data())) throw std::runtime_error("mkdtemp failed");
    path_ = name;
}

TempDir::~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

std::set<std::string> TempDir::names() const {
    std::set<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) out.insert(entry.path().filename().string());
    return out;
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::filesystem::path example(const std::string& name) { return std::filesystem::path(FIRTP_EXAMPLES) / name; }

bool gnuplot_on_path() {
    const char* path = std::getenv("PATH");
    std::string_view dirs = path ? path : "";
    while (!dirs.empty()) {
        const std::size_t colon = dirs.find(':');
        const std::string candidate = std::string(dirs.substr(0, colon)) + "/gnuplot";
        if (access(candidate.c_str(), X_OK) == 0) return true;
        dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
    }
    return false;
}

}  // namespace firtp::cli_test
