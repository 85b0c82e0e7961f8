// One G-code line as words: comments and blanks stripped, numbers read, each letter and modal
// group checked to appear once. Internal to the G-code reader.
#pragma once

#include <firtp/gcode.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace firtp::gcode {

// Where errors point: the file and the line being read.
struct Where {
    const std::string& file;
    int line;
    [[noreturn]] void fail(int column, const std::string& message) const {
        throw GcodeError(file, line, column, message);
    }
};

struct Char {
    char c;
    int column;  // 1-based, in the source line
};

struct Word {
    char letter;       // upper case
    int column;
    std::string text;  // as written, blanks removed, e.g. "G61.1"
    double value;
};

// The line without comments and blanks; blanks may split words and numbers ("X 1 . 5").
std::vector<Char> strip(std::string_view raw, const Where& at);

// The word starting at chars[i]; i moves past it.
Word read_word(const std::vector<Char>& chars, std::size_t& i, const Where& at);

enum Group { motion, plane, units, distance, arc_distance, feed_mode, control, group_count };

// G code in tenths (G61.1 -> 611) as written, e.g. "G90.1".
std::string g_name(int tenths);

// The words of one line, checked as they are read: one word per letter, one G code per modal
// group, axis words only for axes the machine has.
class LineWords {
public:
    explicit LineWords(int machine_axes) : axes_(machine_axes) {}

    void add(const Word& word, const Where& at);

    const Word* get(char letter) const {
        const auto& slot = letter_[static_cast<std::size_t>(letter - 'A')];
        return slot ? &*slot : nullptr;
    }
    const Word* g(Group group) const { return g_[group] ? &*g_[group] : nullptr; }
    int code(Group group) const { return code_[group]; }  // valid when g(group)

    // The leftmost of the given letters on this line, or nullptr.
    const Word* first_of(std::string_view letters) const;

private:
    void add_g(const Word& word, const Where& at);

    int axes_;
    std::array<std::optional<Word>, 26> letter_{};
    std::array<std::optional<Word>, group_count> g_{};
    std::array<int, group_count> code_{};
};

}  // namespace firtp::gcode
