#include "gnuplot_pipe.hpp"

#include <firtp/text_cat.hpp>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include <sys/wait.h>
#include <unistd.h>

namespace firtp::cli {

std::filesystem::path find_gnuplot() {
    const char* path = std::getenv("PATH");
    std::string_view dirs = path ? path : "";
    while (!dirs.empty()) {
        const std::size_t colon = dirs.find(':');
        const std::string_view dir = dirs.substr(0, colon);
        const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / "gnuplot";
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
        dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
    }
    throw std::runtime_error("the plots (--plot, --report, simulate --out) need gnuplot, which is not on PATH: "
                             "install the Debian package gnuplot-nox (apt-get install gnuplot-nox)");
}

void run_gnuplot(const std::filesystem::path& gnuplot, const std::string& script) {
    const std::string command = cat("'", gnuplot.string(), "'");  // PATH entries hold no quotes in practice
    // A gnuplot that dies early must not kill us with SIGPIPE; its exit status tells.
    const auto previous = std::signal(SIGPIPE, SIG_IGN);
    FILE* pipe = ::popen(command.c_str(), "w");
    if (!pipe) {
        std::signal(SIGPIPE, previous);
        throw std::runtime_error(cat("cannot start ", gnuplot.string()));
    }
    const bool written = std::fwrite(script.data(), 1, script.size(), pipe) == script.size();
    const int status = ::pclose(pipe);
    std::signal(SIGPIPE, previous);
    if (!written || status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("gnuplot failed to draw the plot (see its message above)");
}

std::string gnuplot_quote(const std::string& text) {
    // Single quotes: no escapes, no `command` substitution; line breaks joined in as "\n".
    std::string out = "'";
    for (char c : text) {
        if (c == '\n') out += "'.\"\\n\".'";
        else if (c == '\'') out += "''";
        else out += c;
    }
    return out + "'";
}

}  // namespace firtp::cli
