#include "options.hpp"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace firtp::tp_check {

void usage(const std::string& why) {
    std::cerr << "firtp-tp-check: " << why << "\n"
              << "usage: firtp-tp-check SAMPLES --ini INI --program NGC [--tp-samples FILE] [--tolerance MM]\n"
                 "                      [--corner-tolerance MM] [--limits] [--jerk J] [--cycle-time S[:WITHIN]]\n"
                 "                      [--lines N,N,...] [--stopped] [--hold S] [--reference CSV [--within MM]]\n"
                 "                      [--tsc-hz HZ] [--json FILE]\n"
                 "       firtp-tp-check --tsc-hz\n";
    std::exit(2);
}

namespace {

double number(const std::string& option, const std::string& text) {
    char* end = nullptr;
    const double d = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(d)) usage(option + ": '" + text + "' is not a number");
    return d;
}

void cycle_time(const std::string& text, Options& o) {
    char* end = nullptr;
    o.cycle_time = std::strtod(text.c_str(), &end);
    if (*end == ':') o.cycle_within = std::strtod(end + 1, &end);
    if (*end != '\0' || !(o.cycle_time > 0.0) || !(o.cycle_within >= 0.0)) usage("--cycle-time S[:WITHIN]");
}

void lines(const std::string& text, Options& o) {
    std::istringstream list(text);
    for (std::string n; std::getline(list, n, ',');) o.expected_lines.push_back(std::strtol(n.c_str(), nullptr, 10));
}

using Text = const std::string&;

// The options that take a value, each with what it sets.
struct Valued {
    const char* name;
    void (*set)(Text option, Text value, Options& o);
};
constexpr Valued valued_options[] = {
    {"--ini", [](Text, Text v, Options& o) { o.ini_path = v; }},
    {"--program", [](Text, Text v, Options& o) { o.program_path = v; }},
    {"--tp-samples", [](Text, Text v, Options& o) { o.tp_samples_path = v; }},
    {"--json", [](Text, Text v, Options& o) { o.json_path = v; }},
    {"--reference", [](Text, Text v, Options& o) { o.reference_path = v; }},
    {"--tolerance", [](Text a, Text v, Options& o) { o.tolerance = number(a, v); }},
    {"--corner-tolerance", [](Text a, Text v, Options& o) { o.corner_tolerance = number(a, v); }},
    {"--jerk", [](Text a, Text v, Options& o) { o.jerk = number(a, v); }},
    {"--tsc-hz", [](Text a, Text v, Options& o) { o.tsc_hz = number(a, v); }},
    {"--hold", [](Text a, Text v, Options& o) { o.hold = number(a, v); }},
    {"--within", [](Text a, Text v, Options& o) { o.within = number(a, v); }},
    {"--cycle-time", [](Text, Text v, Options& o) { cycle_time(v, o); }},
    {"--lines", [](Text, Text v, Options& o) { lines(v, o); }},
};

const Valued* find_valued(Text option) {
    for (const Valued& v : valued_options)
        if (option == v.name) return &v;
    return nullptr;
}

}  // namespace

Options parse_options(const std::vector<std::string>& args) {
    Options o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (const Valued* v = find_valued(a)) {
            if (i + 1 >= args.size()) usage(a + " needs a value");
            v->set(a, args[++i], o);
        } else if (a == "--limits") o.limits = true;
        else if (a == "--stopped") o.stopped = true;
        else if (!a.empty() && a[0] == '-') usage("unknown option " + a);
        else if (o.samples_path.empty()) o.samples_path = a;
        else usage("one samples file only");
    }
    if (o.samples_path.empty() || o.ini_path.empty() || o.program_path.empty())
        usage("SAMPLES, --ini and --program are needed");
    return o;
}

}  // namespace firtp::tp_check
