// Running gnuplot with a script fed through a pipe (no temporary script or data files).
#pragma once

#include <filesystem>
#include <string>

namespace firtp::cli {

// gnuplot's path on PATH; throws std::runtime_error naming the Debian package when it is missing.
std::filesystem::path find_gnuplot();

// Feeds `script` to gnuplot's stdin; throws std::runtime_error when gnuplot fails.
void run_gnuplot(const std::filesystem::path& gnuplot, const std::string& script);

// A gnuplot string expression for `text`, taken literally; '\n' becomes a line break.
std::string gnuplot_quote(const std::string& text);

}  // namespace firtp::cli
