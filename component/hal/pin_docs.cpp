// firtp_pin_docs: the pin tables of docs/GUIDE.md and docs/man/firtp.9, from pin_table.hpp.
//
//   firtp_pin_docs --check GUIDE.md firtp.9   exit 1 (and say where) when a document differs
//   firtp_pin_docs --write GUIDE.md firtp.9   rewrite the tables in place
//
// Each table lies between a begin and an end marker line (a comment in either format).
#include <firtp/hal/pin_table.hpp>

#include <fstream>
#include <iterator>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct PinDoc {
    std::string name;  // after "firtp.", %d for the axis
    std::string type, direction, doc;
};

const std::vector<PinDoc>& pins() {
#define FIRTP_PIN_DOC(member, name, type, direction, doc) PinDoc{name, #type, #direction, doc},
    static const std::vector<PinDoc> list{
        FIRTP_AXIS_PINS(FIRTP_PIN_DOC) FIRTP_TARGET_PINS(FIRTP_PIN_DOC) FIRTP_PINS(FIRTP_PIN_DOC)};
#undef FIRTP_PIN_DOC
    return list;
}

std::string replace_all(std::string_view text, std::string_view from, std::string_view to) {
    std::string out;
    std::size_t begin = 0;
    for (std::size_t at = text.find(from); at != std::string_view::npos; at = text.find(from, begin)) {
        out.append(text.substr(begin, at - begin)).append(to);
        begin = at + from.size();
    }
    return out.append(text.substr(begin));
}

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return text;
}

std::string markdown() {
    std::ostringstream out;
    out << "| pin | type | |\n|---|---|---|\n";
    for (const PinDoc& p : pins())
        out << "| `firtp." << replace_all(p.name, "%d", "N") << "` | " << p.type << ' ' << lower(p.direction) << " | "
            << p.doc << " |\n";
    return out.str();
}

std::string man() {
    std::ostringstream out;
    for (const PinDoc& p : pins()) {
        const std::string name = replace_all(replace_all(p.name, "-", "\\-"), "%d", "\\fIN\\fB");
        out << ".TP\n\\fBfirtp." << name << "\\fR " << p.type << ' ' << lower(p.direction) << '\n'
            << replace_all(p.doc, "-", "\\-") << ".\n";
    }
    return out.str();
}

struct Document {
    std::string path, begin, end, table;
};

// The file with its table replaced; empty when a marker is missing.
std::string with_table(const std::string& text, const Document& d) {
    const std::size_t begin = text.find(d.begin);
    const std::size_t end = text.find(d.end);
    if (begin == std::string::npos || end == std::string::npos || end < begin) return {};
    const std::size_t from = text.find('\n', begin) + 1;
    return text.substr(0, from) + d.table + text.substr(end);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string mode = argc == 4 ? argv[1] : "";
    if (mode != "--check" && mode != "--write") {
        std::cerr << "usage: firtp_pin_docs --check|--write GUIDE.md firtp.9\n";
        return 2;
    }
    const Document documents[] = {
        {argv[2], "<!-- pins: begin", "<!-- pins: end", markdown()},
        {argv[3], ".\\\" pins: begin", ".\\\" pins: end", man()}};
    int status = 0;
    for (const Document& d : documents) {
        std::ifstream in(d.path);
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const std::string expected = with_table(text, d);
        if (!in || expected.empty()) {
            std::cerr << d.path << ": no pin table between '" << d.begin << "' and '" << d.end << "'\n";
            status = 1;
        } else if (expected != text) {
            if (mode == "--write") {
                std::ofstream(d.path) << expected;
                std::cout << "wrote the pin table of " << d.path << "\n";
            } else {
                std::cerr << d.path << ": the pin table differs from component/hal/include/firtp/hal/pin_table.hpp "
                          << "(firtp_pin_docs --write rewrites it)\n";
                status = 1;
            }
        }
    }
    return status;
}
