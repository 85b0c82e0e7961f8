#include <firtp/ini.hpp>

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace firtp {
namespace {

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\f\v");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r\f\v");
    return s.substr(first, last - first + 1);
}

[[noreturn]] void fail(const std::string& file, int line, const std::string& message) {
    throw ConfigError(cat(file, ":", std::to_string(line), ": ", message));
}

}  // namespace

IniFile IniFile::read(const std::filesystem::path& path) {
    std::error_code ec;
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path, ec)) fail(path.string(), 0, "cannot open file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse(text.str(), path.string());
}

IniFile IniFile::parse(std::string_view text, std::string file_name) {
    IniFile ini;
    ini.file_ = std::move(file_name);
    std::string section;
    int line_number = 0;
    for (std::size_t pos = 0; pos <= text.size();) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        const std::string_view line = trim(text.substr(pos, end - pos));
        pos = end + 1;
        ++line_number;

        if (line.empty() || line.front() == '#' || line.front() == ';') continue;
        if (line.front() == '[') {
            const auto close = line.find(']');
            if (close == std::string_view::npos) fail(ini.file_, line_number, "section header is missing ']'");
            if (!trim(line.substr(close + 1)).empty())
                fail(ini.file_, line_number, "unexpected text after the section header");
            section = std::string(trim(line.substr(1, close - 1)));
            if (section.empty()) fail(ini.file_, line_number, "empty section name '[]'");
            continue;
        }
        const auto eq = line.find('=');
        if (eq == std::string_view::npos)
            fail(ini.file_, line_number, "expected KEY = VALUE, a [SECTION] or a comment");
        const std::string_view key = trim(line.substr(0, eq));
        if (key.empty()) fail(ini.file_, line_number, "missing key before '='");
        if (section.empty()) fail(ini.file_, line_number, "KEY = VALUE before any [SECTION]");
        ini.entries_.push_back({section, std::string(key), std::string(trim(line.substr(eq + 1))), line_number});
    }
    return ini;
}

const IniFile::Entry* IniFile::find(std::string_view section, std::string_view key) const {
    for (const Entry& e : entries_)
        if (e.section == section && e.key == key) return &e;
    return nullptr;
}

std::vector<const IniFile::Entry*> IniFile::section(std::string_view section) const {
    std::vector<const Entry*> out;
    for (const Entry& e : entries_)
        if (e.section == section) out.push_back(&e);
    return out;
}

std::optional<double> IniFile::number(std::string_view section, std::string_view key) const {
    const Entry* e = find(section, key);
    if (e == nullptr) return std::nullopt;
    std::string_view text = e->value;
    if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc{} || ptr != text.data() + text.size() || !std::isfinite(value))
        fail(file_, e->line, cat("[", e->section, "]", e->key, ": '", e->value, "' is not a number"));
    return value;
}

}  // namespace firtp
