#include "recording.hpp"

#include "options.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace firtp::tp_check {
namespace {

constexpr double position_scale = 1099511627776.0;  // 2^40, as record.hal's scale components
constexpr std::size_t columns = 7;

using Words = std::vector<std::string>;

// Whitespace-separated lines of at least `width` words; "overrun" lines counted, not kept.
std::vector<Words> read_rows(const std::string& path, std::size_t width, long& overruns) {
    std::ifstream in(path);
    if (!in) usage("cannot read " + path);
    std::vector<Words> rows;
    std::string text;
    overruns = 0;
    while (std::getline(in, text)) {
        std::istringstream words(text);
        Words row;
        for (std::string w; words >> w;) row.push_back(w);
        if (row.empty()) continue;
        if (row[0] == "overrun") {
            ++overruns;
            continue;
        }
        if (row.size() < width) usage(path + ": a line with " + std::to_string(row.size()) + " columns, expected " +
                                      std::to_string(width));
        rows.push_back(row);
    }
    return rows;
}

Row to_row(const Words& r) {
    Row row;
    for (int a = 0; a < 3; ++a) row.position[a] = std::strtod(r[a].c_str(), nullptr) / position_scale;
    row.line = std::strtol(r[3].c_str(), nullptr, 10);
    row.controller_clocks = std::strtod(r[4].c_str(), nullptr);
    row.command_clocks = std::strtod(r[5].c_str(), nullptr);
    row.in_position = r[6] == "1";
    return row;
}

double number(const std::string& word) { return std::strtod(word.c_str(), nullptr); }

}  // namespace

Recording read_recording(const std::string& path) {
    Recording recording;
    const std::vector<Words> raw = read_rows(path, columns, recording.overruns);
    if (raw.size() < 2) usage(path + ": fewer than two samples");
    for (const Words& r : raw) recording.rows.push_back(to_row(r));
    return recording;
}

Motion find_motion(const std::vector<Row>& rows) {
    Motion m{0, rows.size() - 1};
    while (m.first + 1 < rows.size() && rows[m.first + 1].position == rows[m.first].position) ++m.first;
    while (m.last > m.first && rows[m.last - 1].position == rows[m.last].position) --m.last;
    return m;
}

std::vector<AxisState> motion_samples(const std::vector<Row>& rows, Motion motion, double period) {
    std::vector<AxisState> samples;
    for (std::size_t k = motion.first; k <= motion.last; ++k) {
        AxisState s;
        s.time = static_cast<double>(k - motion.first) * period;
        s.position = rows[k].position;
        samples.push_back(s);
    }
    return samples;
}

double longest_rest(const std::vector<Row>& rows, Motion motion, double period) {
    double longest = 0.0;
    for (std::size_t k = motion.first + 1, run = 0; k <= motion.last; ++k) {
        run = rows[k].position == rows[k - 1].position ? run + 1 : 0;
        longest = std::max(longest, static_cast<double>(run) * period);
    }
    return longest;
}

std::vector<long> lines_while_moving(const std::vector<Row>& rows, Motion motion) {
    std::vector<long> lines;
    for (std::size_t k = motion.first; k <= motion.last; ++k)
        if (rows[k].line != 0 && (lines.empty() || lines.back() != rows[k].line)) lines.push_back(rows[k].line);
    return lines;
}

std::vector<AxisVector> read_reference(const std::string& path) {
    std::ifstream in(path);
    if (!in) usage("cannot read " + path);
    std::vector<AxisVector> plan;
    std::string row;
    std::getline(in, row);  // header
    while (std::getline(in, row)) {
        std::istringstream fields(row);
        std::string field;
        AxisVector p = AxisVector::Zero();
        std::getline(fields, field, ',');  // t
        for (int a = 0; a < 3 && std::getline(fields, field, ','); ++a) p[a] = number(field);
        plan.push_back(p);
    }
    return plan;
}

Stats stats(std::vector<double> v) {
    Stats s;
    s.count = v.size();
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    s.median = v[v.size() / 2];
    s.p99 = v[std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(v.size()))) - 1)];
    s.max = v.back();
    return s;
}

nlohmann::json stats_json(const Stats& s) {
    return {{"median_us", s.median}, {"p99_us", s.p99}, {"max_us", s.max}, {"cycles", s.count}};
}

MotionCpu motion_cpu(const std::vector<Row>& rows, Motion motion, double tsc_hz) {
    std::vector<double> controller, command;
    for (std::size_t k = motion.first; k <= motion.last; ++k) {
        controller.push_back(rows[k].controller_clocks / tsc_hz * 1e6);
        command.push_back(rows[k].command_clocks / tsc_hz * 1e6);
    }
    return {stats(controller), stats(command)};
}

nlohmann::json firtp_tp_report(const std::string& path) {
    long overruns = 0;
    const std::vector<Words> raw = read_rows(path, 5, overruns);  // adds add-ns cycle-ns plan-ns planned
    std::vector<double> add, cycle, plan;
    long most_planned = 0, previous_adds = -1;
    for (const Words& r : raw) {
        const long adds = std::strtol(r[0].c_str(), nullptr, 10);
        if (previous_adds >= 0 && adds != previous_adds) add.push_back(number(r[1]) / 1e3);
        previous_adds = adds;
        cycle.push_back(number(r[2]) / 1e3);
        plan.push_back(number(r[3]) / 1e3);
        most_planned = std::max(most_planned, std::strtol(r[4].c_str(), nullptr, 10));
    }
    return {{"add", stats_json(stats(add))},
            {"run_cycle", stats_json(stats(cycle))},
            {"planning", stats_json(stats(plan))},
            {"most_blocks_planned_in_a_period", most_planned},
            {"overruns", overruns}};
}

double measure_tsc_hz() {
#if defined(__x86_64__) || defined(__i386__)
    const auto t0 = std::chrono::steady_clock::now();
    const unsigned long long c0 = __rdtsc();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const unsigned long long c1 = __rdtsc();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return static_cast<double>(c1 - c0) / seconds;
#else
    return 0.0;
#endif
}

}  // namespace firtp::tp_check
