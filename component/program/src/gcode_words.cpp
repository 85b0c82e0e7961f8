#include "gcode_words.hpp"

#include <firtp/text_cat.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace firtp::gcode {
namespace {

constexpr std::string_view supported_letters = "ABCFGIJKMNPQRUVWXYZ";

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
char upper(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::optional<Group> group_of(int tenths) {
    switch (tenths) {
        case 0: case 10: case 20: case 30: return motion;
        case 170: case 180: case 190: return plane;
        case 200: case 210: return units;
        case 900: case 910: return distance;
        case 901: case 911: return arc_distance;
        case 940: return feed_mode;
        case 610: case 611: case 640: return control;
        default: return std::nullopt;
    }
}

// G code in tenths (G61.1 -> 611); throws for codes firtp does not plan.
int g_code(const Word& w, const Where& at) {
    const double tenths = w.value * 10.0;
    const bool exact = w.value >= 0.0 && w.value < 1000.0 && std::abs(tenths - std::round(tenths)) < 1e-6;
    const int code = exact ? static_cast<int>(std::lround(tenths)) : -1;
    if (code < 0 || !group_of(code)) at.fail(w.column, cat(exact ? g_name(code) : w.text, " is not supported"));
    return code;
}

}  // namespace

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

std::string g_name(int tenths) {
    return tenths % 10 == 0 ? cat("G", std::to_string(tenths / 10))
                            : cat("G", std::to_string(tenths / 10), ".", std::to_string(tenths % 10));
}

void LineWords::add(const Word& word, const Where& at) {
    const auto axis = std::find(axis_letters.begin(), axis_letters.end(), word.letter);
    if (axis != axis_letters.end() && axis - axis_letters.begin() >= axes_)
        at.fail(word.column, cat("axis word '", word.letter, "' but the machine has ", std::to_string(axes_), " axes"));
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

const Word* LineWords::first_of(std::string_view letters) const {
    const Word* first = nullptr;
    for (const char letter : letters) {
        const Word* w = get(letter);
        if (w != nullptr && (first == nullptr || w->column < first->column)) first = w;
    }
    return first;
}

void LineWords::add_g(const Word& word, const Where& at) {
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

}  // namespace firtp::gcode
