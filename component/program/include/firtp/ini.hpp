// LinuxCNC-style INI files: [SECTION] headers, KEY = VALUE, '#' and ';' comment lines,
// repeated keys allowed (the first one counts, as in LinuxCNC's IniFile).
// Neither Boost.PropertyTree (';' comments only, no repeated keys) nor program_options'
// config parser (no line numbers in its errors) reads this dialect with the errors we need.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace firtp {

// what() is "file:line: message" (line 0 when the problem is a missing key or file).
class ConfigError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class IniFile {
public:
    struct Entry {
        std::string section;  // upper case as written
        std::string key;
        std::string value;    // trimmed
        int line = 0;
    };

    static IniFile read(const std::filesystem::path& path);                     // throws ConfigError
    static IniFile parse(std::string_view text, std::string file_name);         // throws ConfigError

    const std::string& file_name() const { return file_; }
    const Entry* find(std::string_view section, std::string_view key) const;  // first match or nullptr
    std::vector<const Entry*> section(std::string_view section) const;         // every entry of a section

    // A finite number, or nullopt when absent; ConfigError "file:line: [SECTION]KEY: ..." when not a number.
    std::optional<double> number(std::string_view section, std::string_view key) const;

private:
    std::string file_;
    std::vector<Entry> entries_;
};

}  // namespace firtp
