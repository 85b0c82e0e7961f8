#include <firtp/gcode.hpp>

#include "gcode_interpreter.hpp"
#include "gcode_words.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace firtp {

GcodeError::GcodeError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(cat(file, ":", std::to_string(line), ":", std::to_string(column), ": ", message)),
      file_(std::move(file)), line_(line), column_(column) {}

Program parse_gcode(std::string_view text, const std::string& file_name, const MachineConfig& machine,
                    const AxisVector& start) {
    using namespace gcode;
    Program program{file_name, start, {}};
    Interpreter interpreter(machine, start, program.blocks);
    bool started = false;  // a line with content was seen (a '%' there opens the program)
    int line_number = 0;
    for (std::size_t pos = 0; pos <= text.size();) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        const std::string_view raw = text.substr(pos, end - pos);
        pos = end + 1;
        const Where at{file_name, ++line_number};

        const std::vector<Char> chars = strip(raw, at);
        if (chars.empty()) continue;
        if (chars.size() == 1 && chars[0].c == '%') {
            if (started) break;  // closing '%': the rest is ignored
            started = true;
            continue;
        }
        started = true;
        LineWords words(machine.limits.axes);
        for (std::size_t i = 0; i < chars.size();) words.add(read_word(chars, i, at), at);
        if (interpreter.run(words, at)) break;  // M2 / M30
    }
    return program;
}

Program read_gcode(const std::filesystem::path& path, const MachineConfig& machine, const AxisVector& start) {
    std::error_code ec;
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path, ec)) throw GcodeError(path.string(), 0, 0, "cannot open file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_gcode(text.str(), path.string(), machine, start);
}

}  // namespace firtp
