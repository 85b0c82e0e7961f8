#include <firtp/gcode.hpp>

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

namespace firtp {
namespace {

}  // namespace

GcodeError::GcodeError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(cat(file, ":", std::to_string(line), ":", std::to_string(column), ": ", message)),
      file_(std::move(file)), line_(line), column_(column) {}

namespace {

constexpr double mm_per_inch = 25.4;
constexpr double zero_length = 1e-9;  // mm; shorter moves are dropped, as LinuxCNC's canon drops empty moves
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::string_view supported_letters = "FGMNPXYZ";

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

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
char upper(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The line without comments and blanks; blanks may split words and numbers ("X 1 . 5").
std::vector<Char> strip(std::string_view raw, const Where& at) {
    std::vector<Char> out;
    int comment = 0;  // column of the open '(' or 0
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const char c = raw[i];
        const int column = static_cast<int>(i) + 1;
        if (comment != 0) {
            if (c == ')') comment = 0;
            else if (c == '(') at.fail(column, "'(' inside a comment: comments do not nest");
        } else if (c == '(') {
            comment = column;
        } else if (c == ';') {
            break;
        } else if (!is_blank(c)) {
            out.push_back({c, column});
        }
    }
    if (comment != 0) at.fail(comment, "comment is not closed: missing ')'");
    return out;
}

// Number after a word's letter: optional sign, digits with at most one '.', no exponent.
Word read_word(const std::vector<Char>& chars, std::size_t& i, const Where& at) {
    const Char head = chars[i];
    const char letter = upper(head.c);
    if (head.c == '%') at.fail(head.column, "'%' must be alone on its line");
    if (!is_letter(head.c)) at.fail(head.column, cat("unexpected character '", head.c, "'"));
    if (supported_letters.find(letter) == std::string_view::npos)
        at.fail(head.column, cat("word '", letter, "' is not supported"));

    const std::size_t n = chars.size();
    std::size_t j = i + 1;
    std::string number;
    int digits = 0;
    if (j < n && (chars[j].c == '+' || chars[j].c == '-')) number += chars[j++].c;
    for (; j < n && is_digit(chars[j].c); ++j, ++digits) number += chars[j].c;
    if (j < n && chars[j].c == '.') number += chars[j++].c;
    for (; j < n && is_digit(chars[j].c); ++j, ++digits) number += chars[j].c;

    const auto word_ends = [&](std::size_t k) {
        if (k == n) return true;
        const char c = chars[k].c;
        return !(is_digit(c) || c == '.' || c == '+' || c == '-' || upper(c) == 'E');
    };
    if (number.empty() && word_ends(j)) at.fail(head.column, cat("word '", letter, "' has no number"));
    if (digits == 0 || !word_ends(j)) {
        std::string shown = letter + number;
        for (; !word_ends(j); ++j) shown += chars[j].c;
        at.fail(head.column, cat("malformed number in '", shown,
                                     "': write digits with at most one decimal point and no exponent"));
    }
    i = j;
    const std::size_t skip = number.front() == '+' ? 1 : 0;
    double value = 0.0;
    std::from_chars(number.data() + skip, number.data() + number.size(), value);
    return {letter, head.column, letter + number, value};
}

enum Group { motion, plane, units, distance, control, group_count };

std::string g_name(int tenths) {
    return tenths % 10 == 0 ? cat("G", std::to_string(tenths / 10))
                             : cat("G", std::to_string(tenths / 10), ".", std::to_string(tenths % 10));
}

std::optional<Group> group_of(int tenths) {
    switch (tenths) {
        case 0: case 10: return motion;
        case 170: return plane;
        case 200: case 210: return units;
        case 900: case 910: return distance;
        case 610: case 611: case 640: return control;
        default: return std::nullopt;
    }
}

// G code in tenths (G61.1 -> 611); throws for codes firtp does not plan.
int g_code(const Word& w, const Where& at) {
    const double tenths = w.value * 10.0;
    const bool exact = w.value >= 0.0 && w.value < 1000.0 && std::abs(tenths - std::round(tenths)) < 1e-6;
    const int code = exact ? static_cast<int>(std::lround(tenths)) : -1;
    if (code == 180 || code == 190)
        at.fail(w.column, cat(g_name(code), " is not supported: firtp plans in the XY plane only (G17)"));
    if (code < 0 || !group_of(code)) at.fail(w.column, cat(exact ? g_name(code) : w.text, " is not supported"));
    return code;
}

// The words of one line, checked as they are read: one word per letter, one G code per modal group.
class LineWords {
public:
    void add(const Word& word, const Where& at) {
        auto& slot = letter_[static_cast<std::size_t>(word.letter - 'A')];
        if (word.letter == 'G') {
            add_g(word, at);
            return;
        }
        if (word.letter == 'M') {
            const bool integral = word.value == std::floor(word.value) && std::abs(word.value) < 1000.0;
            const std::string name = integral ? cat("M", std::to_string(static_cast<int>(word.value))) : word.text;
            if (name != "M2" && name != "M30") at.fail(word.column, cat(name, " is not supported"));
            if (slot)
                at.fail(word.column, cat("M", std::to_string(static_cast<int>(slot->value)), " and ", name,
                                         " are in the same modal group: use one per line"));
        } else if (slot) {
            at.fail(word.column, cat("more than one ", word.letter, " word on this line"));
        }
        slot = word;
    }

    const Word* get(char letter) const {
        const auto& slot = letter_[static_cast<std::size_t>(letter - 'A')];
        return slot ? &*slot : nullptr;
    }
    const Word* g(Group group) const { return g_[group] ? &*g_[group] : nullptr; }
    int code(Group group) const { return code_[group]; }  // valid when g(group)

private:
    void add_g(const Word& word, const Where& at) {
        const int code = g_code(word, at);
        const Group group = *group_of(code);
        if (g_[group]) {
            const int first = code_[group];
            at.fail(word.column, first == code ? cat(g_name(code), " appears twice on this line")
                                               : cat(g_name(first), " and ", g_name(code),
                                                     " are in the same modal group: use one per line"));
        }
        g_[group] = word;
        code_[group] = code;
    }

    std::array<std::optional<Word>, 26> letter_{};
    std::array<std::optional<Word>, group_count> g_{};
    std::array<int, group_count> code_{};
};

struct Modal {
    int motion = -1;           // 0 (G0), 10 (G1) or -1 before the first
    double scale = 1.0;        // mm per program unit (G21 / G20)
    bool incremental = false;  // G91
    Termination termination = Termination::blend;
    double tolerance = 0.0;    // mm
    double feed = 0.0;         // mm/min, kept across G20/G21 as LinuxCNC does
};

// Speed limit along unit direction u: [TRAJ]MAX_LINEAR_VELOCITY and each axis' MAX_VELOCITY.
double speed_cap(const Eigen::Vector3d& u, const MachineLimits& limits) {
    double cap = limits.max_linear_velocity > 0.0 ? limits.max_linear_velocity : infinity;
    for (Eigen::Index a = 0; a < 3; ++a) {
        const double v = limits.axis[static_cast<std::size_t>(a)].max_velocity;
        if (u[a] != 0.0 && v > 0.0) cap = std::min(cap, v / std::abs(u[a]));
    }
    return cap;
}

class Interpreter {
public:
    Interpreter(const MachineConfig& machine, const AxisVector& start, std::vector<Block>& blocks)
        : machine_(machine), position_(start), blocks_(blocks) {
        state_.tolerance = machine.default_tolerance;
    }

    // Runs one line in LinuxCNC's order (F, units, G61/G64, G90/G91, motion, M2); true when it ends the program.
    bool run(const LineWords& w, const Where& at) {
        const Word* f = w.get('F');
        const Word* p = w.get('P');
        if (f != nullptr && f->value < 0.0) at.fail(f->column, cat("negative feed rate '", f->text, "'"));
        if (f != nullptr) state_.feed = f->value * state_.scale;
        if (w.g(units) != nullptr) state_.scale = w.code(units) == 200 ? mm_per_inch : 1.0;
        const bool g64 = w.g(control) != nullptr && w.code(control) == 640;
        if (p != nullptr && !g64) at.fail(p->column, "P word without G64: only G64 takes P here");
        if (p != nullptr && p->value < 0.0) at.fail(p->column, "G64 P must not be negative");
        if (w.g(control) != nullptr) {
            state_.termination = g64 ? Termination::blend : Termination::exact_stop;
            state_.tolerance = !g64 ? 0.0
                               : p == nullptr ? machine_.default_tolerance
                               : p->value == 0.0 ? infinity : p->value * state_.scale;
        }
        if (w.g(distance) != nullptr) state_.incremental = w.code(distance) == 910;
        if (w.g(motion) != nullptr) state_.motion = w.code(motion);
        if (w.get('X') != nullptr || w.get('Y') != nullptr || w.get('Z') != nullptr) move(w, at);
        return w.get('M') != nullptr;
    }

private:
    void move(const LineWords& w, const Where& at) {
        const Word* first = nullptr;
        for (const char letter : {'X', 'Y', 'Z'}) {
            const Word* a = w.get(letter);
            if (a != nullptr && (first == nullptr || a->column < first->column)) first = a;
        }
        const int column = w.g(motion) != nullptr ? w.g(motion)->column : first->column;
        if (state_.motion < 0)
            at.fail(first->column, cat(first->letter, " word with no motion in effect: program G0 or G1 first"));
        const bool rapid = state_.motion == 0;
        if (!rapid && state_.feed <= 0.0)
            at.fail(column, "cannot do G1 with zero feed rate: program an F word first");

        AxisVector target = position_;
        for (Eigen::Index a = 0; a < 3; ++a) {
            const Word* word = w.get(axis_letters[static_cast<std::size_t>(a)]);
            if (word != nullptr) target[a] = (state_.incremental ? position_[a] : 0.0) + word->value * state_.scale;
        }
        const Eigen::Vector3d d = target.head<3>() - position_.head<3>();
        const double length = d.norm();
        if (length <= zero_length) return;
        const double cap = speed_cap(d / length, machine_.limits);
        if (rapid && !std::isfinite(cap))
            at.fail(column, "G0 needs the axes' MAX_VELOCITY: this machine has no rapid speed");

        Block block;
        block.target = target;
        block.feed = rapid ? cap : std::min(state_.feed / 60.0, cap);
        block.termination = state_.termination;
        block.tolerance = state_.tolerance;
        block.type = rapid ? MotionType::traverse : MotionType::feed;
        block.line = at.line;
        blocks_.push_back(block);
        position_ = target;
    }

    const MachineConfig& machine_;
    AxisVector position_;
    std::vector<Block>& blocks_;
    Modal state_;
};

}  // namespace

Program parse_gcode(std::string_view text, const std::string& file_name, const MachineConfig& machine,
                    const AxisVector& start) {
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
        LineWords words;
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
