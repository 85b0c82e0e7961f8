// Helper for the machine (INI) tests: the error a text gives when loaded as "mill.ini".
#pragma once

#include <firtp/ini.hpp>
#include <firtp/machine.hpp>

#include <string>

namespace firtp::test {

// "no error" or the ConfigError's message.
inline std::string load_error(const std::string& text) {
    try {
        load_machine(IniFile::parse(text, "mill.ini"));
    } catch (const ConfigError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace firtp::test
