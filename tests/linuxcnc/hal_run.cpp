// firtp-lcnc-hal-run: the files of one HAL run of a G-code program through firtp's block pins, in
// real LinuxCNC and in hal-shim, and the comparison of the two recorded trajectories.
//
//   firtp-lcnc-hal-run prepare PROGRAM.ngc INI DIR
//     DIR/linuxcnc.hal  for halrun: LinuxCNC's streamer feeds the blocks, sampler + halsampler
//                       record every period into DIR/samples.txt
//     DIR/blocks.txt    halstreamer's rows: one block on the pins, strobe up, then strobe down
//     DIR/shim.hal      for firtp-hal --no-realtime: the same rows with setp, one `step 1` and
//                       the same pins with getp every period
//     DIR/program.txt   what compare needs: axes, periods, end point
//   firtp-lcnc-hal-run compare DIR SHIM_OUTPUT
//     compares DIR/samples.txt (LinuxCNC) with firtp-hal's output, period by period; prints the
//     largest differences; exit 0 when every period agrees within 1e-9 and both end at rest on
//     the program's end point, 1 otherwise, 2 on bad input.
//
// Both scripts begin with the same lines: the servo thread, loadrt firtp with the machine's
// settings (as firtp run gives them), addf firtp.update, setp firtp.enable 1. Feeding and
// recording differ because hal-shim has no streamer/sampler and runs in virtual time. In one
// period the order is the same in both: block pins set, firtp.update, axis pins read.
//
// halsampler prints floats with %f (6 decimals), too coarse for 1e-9 mm: every float channel goes
// through LinuxCNC's `scale` with gain 2^60 first. Multiplying by a power of two is exact, and from
// |value| >= 2^-27 (7.5e-9) on the product's spacing exceeds 1e-6, so the printed decimals read back
// as the very double recorded; smaller values are off by at most 5e-7 / 2^60 = 4e-25.
#include <firtp/gcode.hpp>
#include <firtp/ini.hpp>
#include <firtp/machine.hpp>
#include <firtp/text_cat.hpp>
#include <firtp/trajectory.hpp>
#include <firtp/types.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using firtp::cat;

constexpr double scale_gain = 1152921504606846976.0;  // 2^60
constexpr double tolerance = 1e-9;
constexpr int rest_periods = 100;            // recorded after the plan's end, at rest

std::string number_text(double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

void write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out.flush()) throw std::runtime_error(cat("cannot write ", path.string()));
}

// Recorded every period, in this order: integers, then per axis position, velocity, acceleration.
struct Channel {
    std::string pin;
    char type;  // sampler cfg letter: u s b f
};

std::vector<Channel> channels(int axes) {
    std::vector<Channel> c{{"firtp.tick", 'u'}, {"firtp.current-line", 's'}, {"firtp.state", 's'},
                           {"firtp.done", 'b'}, {"firtp.rejected", 'u'}};
    for (const char* what : {"pos-cmd", "vel-cmd", "acc-cmd"})
        for (int a = 0; a < axes; ++a) c.push_back({cat("firtp.axis.", std::to_string(a), ".", what), 'f'});
    return c;
}
constexpr int integer_channels = 5;

// Streamer row: target.0..axes-1, feed, tolerance, motion-type, exact-stop, line, program, seq, strobe.
struct RowPin {
    std::string pin;
    char type;
};

std::vector<RowPin> row_pins(int axes) {
    std::vector<RowPin> p;
    for (int a = 0; a < axes; ++a) p.push_back({cat("firtp.block.target.", std::to_string(a)), 'f'});
    p.push_back({"firtp.block.feed", 'f'});
    p.push_back({"firtp.block.tolerance", 'f'});
    p.push_back({"firtp.block.motion-type", 's'});
    p.push_back({"firtp.block.exact-stop", 'b'});
    p.push_back({"firtp.block.line", 's'});
    p.push_back({"firtp.block.program", 'u'});
    p.push_back({"firtp.block.seq", 'u'});
    p.push_back({"firtp.block.strobe", 'b'});
    return p;
}

std::vector<std::vector<std::string>> rows(const firtp::Program& program, int axes) {
    std::vector<std::vector<std::string>> result;
    std::uint32_t seq = 0;
    for (const firtp::Block& b : program.blocks) {
        std::vector<std::string> row;
        for (int a = 0; a < axes; ++a) row.push_back(number_text(b.target[a]));
        row.push_back(number_text(b.feed));
        row.push_back(number_text(b.tolerance));
        row.push_back(b.type == firtp::MotionType::traverse ? "1" : "2");
        row.push_back(b.termination == firtp::Termination::exact_stop ? "1" : "0");
        row.push_back(std::to_string(b.line));
        row.push_back("1");
        row.push_back(std::to_string(++seq));
        row.push_back("1");
        result.push_back(row);
        row.pop_back();  // next period: strobe down, the component lowers ack
        row.emplace_back("0");
        result.push_back(row);
    }
    return result;
}

// The lines both scripts start with: the machine's settings for firtp.so, as firtp run loads it.
std::string common_header(const firtp::MachineConfig& machine) {
    const firtp::PlannerParameters p = machine.planner_parameters();
    std::string load = cat("loadrt firtp axes=", std::to_string(machine.limits.axes),
                           " stages=", std::to_string(p.filters.stages),
                           " tolerance=", number_text(machine.default_tolerance),
                           " meaning=", p.tolerance_meaning == firtp::ToleranceMeaning::contour ? "contour" : "corner",
                           " period_ns=", std::to_string(std::llround(p.period * 1e9)),
                           " max_feed_override=", number_text(p.max_rate),
                           " rate_reserve=", number_text(p.rate_reserve));
    for (int i = 0; i < p.filters.stages; ++i)
        load += cat(" t", std::to_string(i + 1), "=", number_text(p.filters.T[i]));
    auto per_axis = [&](const char* name, double firtp::AxisLimits::*limit) {
        load += cat(" ", name, "=");
        for (int a = 0; a < p.limits.axes; ++a) load += cat(a ? "," : "", number_text(p.limits.axis[a].*limit));
    };
    per_axis("max_velocity", &firtp::AxisLimits::max_velocity);
    per_axis("max_acceleration", &firtp::AxisLimits::max_acceleration);
    per_axis("max_jerk", &firtp::AxisLimits::max_jerk);
    return cat("loadrt threads name1=servo-thread period1=", std::to_string(std::llround(p.period * 1e9)), "\n",
               load, "\n",
               "addf firtp.update servo-thread\n"
               "setp firtp.enable 1\n");
}

int prepare(const std::filesystem::path& ngc, const std::filesystem::path& ini, const std::filesystem::path& dir) {
    const firtp::MachineConfig machine = firtp::load_machine(firtp::IniFile::read(ini));
    const firtp::Program program = firtp::read_gcode(ngc, machine);
    if (program.blocks.empty()) throw std::runtime_error(cat(ngc.string(), ": no moves"));
    if (!program.start.isZero()) throw std::runtime_error(cat(ngc.string(), ": the component starts at 0"));
    const int axes = machine.limits.axes;

    // Periods to record: the plan of the whole program (every block known at once), the periods
    // the pins take to hand the blocks over (two each), then some at rest.
    const firtp::Trajectory plan = firtp::plan_trajectory(machine.planner_parameters(), program.start, program.blocks);
    const auto data = rows(program, axes);
    const long periods = static_cast<long>(plan.samples.size() + data.size()) + rest_periods;

    const std::string header = common_header(machine);
    const auto record = channels(axes);
    const auto feed = row_pins(axes);

    // blocks.txt and linuxcnc.hal
    std::string text;
    for (const auto& row : data) {
        for (std::size_t i = 0; i < row.size(); ++i) text += cat(i ? " " : "", row[i]);
        text += "\n";
    }
    write_file(dir / "blocks.txt", text);

    std::string stream_cfg, sample_cfg;
    for (const RowPin& p : feed) stream_cfg += p.type;
    for (const Channel& c : record) sample_cfg += c.type;
    const int floats = static_cast<int>(record.size()) - integer_channels;
    std::string hal = cat("# ", ngc.filename().string(), " on ", ini.filename().string(),
                          " through firtp's block pins, in LinuxCNC (generated by firtp-lcnc-hal-run)\n", header);
    hal += cat("loadrt streamer depth=", std::to_string(data.size() + 16), " cfg=", stream_cfg, "\n",
               "loadrt sampler depth=", std::to_string(periods + 16), " cfg=", sample_cfg, "\n",
               "loadrt scale count=", std::to_string(floats), "\n",
               "addf streamer.0 servo-thread 1\n");
    for (std::size_t i = 0; i < feed.size(); ++i)
        hal += cat("net row-", std::to_string(i), " streamer.0.pin.", std::to_string(i), " => ", feed[i].pin, "\n");
    for (std::size_t i = 0; i < record.size(); ++i) {
        const std::string sampler_pin = cat("sampler.0.pin.", std::to_string(i));
        if (i < integer_channels) {
            hal += cat("net rec-", std::to_string(i), " ", record[i].pin, " => ", sampler_pin, "\n");
            continue;
        }
        const std::string s = cat("scale.", std::to_string(i - integer_channels));
        hal += cat("addf ", s, " servo-thread\n", "setp ", s, ".gain ", number_text(scale_gain), "\n",
                   "net rec-", std::to_string(i), " ", record[i].pin, " => ", s, ".in\n",
                   "net rec-", std::to_string(i), "-scaled ", s, ".out => ", sampler_pin, "\n");
    }
    hal += cat("addf sampler.0 servo-thread\n",
               "loadusr -w halstreamer -c 0 blocks.txt\n",
               "start\n",
               "loadusr -w halsampler -c 0 -n ", std::to_string(periods), " samples.txt\n",
               "stop\n",
               "show pin sampler.0.overruns\n",
               "show param firtp.update\n");
    write_file(dir / "linuxcnc.hal", hal);

    // shim.hal: the same rows, one period each, then the same pins read.
    std::string shim = cat("# ", ngc.filename().string(), " on ", ini.filename().string(),
                           " through firtp's block pins, in hal-shim (generated by firtp-lcnc-hal-run)\n", header);
    std::vector<std::string> last(feed.size());
    for (long k = 0; k < periods; ++k) {
        if (k < static_cast<long>(data.size()))
            for (std::size_t i = 0; i < feed.size(); ++i)
                if (data[k][i] != last[i]) {
                    shim += cat("setp ", feed[i].pin, " ", data[k][i], "\n");
                    last[i] = data[k][i];
                }
        shim += "step 1\n";
        for (const Channel& c : record) shim += cat("getp ", c.pin, "\n");
    }
    write_file(dir / "shim.hal", shim);

    const firtp::Block& end = program.blocks.back();
    std::string info = cat(std::to_string(axes), " ", std::to_string(periods), " ",
                           std::to_string(program.blocks.size()));
    for (int a = 0; a < axes; ++a) info += cat(" ", number_text(end.target[a]));
    write_file(dir / "program.txt", info + "\n");
    std::cout << program.blocks.size() << " blocks, " << periods << " periods\n";
    return 0;
}

double parse_number(const std::string& text) {
    if (text == "TRUE") return 1;
    if (text == "FALSE") return 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') throw std::runtime_error(cat("not a number: '", text, "'"));
    return v;
}

using Samples = std::vector<std::vector<double>>;

// halsampler: one line a period, the channels separated by spaces; floats scaled by 2^60.
Samples read_linuxcnc(const std::filesystem::path& path, std::size_t width) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(cat("cannot read ", path.string()));
    Samples samples;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::vector<double> s;
        std::string field;
        while (fields >> field) s.push_back(parse_number(field));
        if (s.size() != width)
            throw std::runtime_error(cat(path.string(), ": line ", std::to_string(samples.size() + 1), " has ",
                                         std::to_string(s.size()), " values, not ", std::to_string(width)));
        for (std::size_t i = integer_channels; i < width; ++i) s[i] /= scale_gain;
        samples.push_back(s);
    }
    return samples;
}

// firtp-hal: one value a line, `width` lines a period (echo lines from the script are skipped).
Samples read_shim(const std::filesystem::path& path, std::size_t width) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(cat("cannot read ", path.string()));
    Samples samples;
    std::vector<double> s;
    std::string line;
    while (std::getline(in, line)) {
        s.push_back(parse_number(line));
        if (s.size() == width) samples.push_back(std::exchange(s, {}));
    }
    if (!s.empty()) throw std::runtime_error(cat(path.string(), ": incomplete last period"));
    return samples;
}

int compare(const std::filesystem::path& dir, const std::filesystem::path& shim_output) {
    std::ifstream info(dir / "program.txt");
    int axes = 0;
    long periods = 0;
    std::size_t blocks = 0;
    info >> axes >> periods >> blocks;
    firtp::AxisVector end = firtp::AxisVector::Zero();
    for (int a = 0; a < axes; ++a) info >> end[a];
    if (!info || axes < 1 || axes > firtp::max_axes) throw std::runtime_error("bad program.txt");
    const std::size_t width = integer_channels + 3 * static_cast<std::size_t>(axes);
    const Samples lcnc = read_linuxcnc(dir / "samples.txt", width);
    const Samples shim = read_shim(shim_output, width);

    std::vector<std::string> failures;  // printed after the figures
    auto fail = [&](const std::string& what) { failures.push_back(what); };
    if (static_cast<long>(lcnc.size()) != periods) fail(cat("LinuxCNC recorded ", std::to_string(lcnc.size()),
                                                            " periods, not ", std::to_string(periods)));
    if (static_cast<long>(shim.size()) != periods) fail(cat("hal-shim recorded ", std::to_string(shim.size()),
                                                            " periods, not ", std::to_string(periods)));
    const std::size_t n = std::min(lcnc.size(), shim.size());
    static const char* const integer_names[] = {"tick", "current-line", "state", "done", "rejected"};
    static const char* const kinds[] = {"pos-cmd (mm)", "vel-cmd (mm/s)", "acc-cmd (mm/s^2)"};
    std::vector<double> worst(width, 0.0);
    std::vector<std::size_t> worst_at(width, 0);
    std::size_t integer_mismatches = 0;
    for (std::size_t k = 0; k < n; ++k) {
        // every period recorded once, in order: firtp.tick counts the periods firtp.update ran
        if (lcnc[k][0] != static_cast<double>(k + 1) && integer_mismatches++ < 5)
            fail(cat("LinuxCNC sample ", std::to_string(k), " has tick ", number_text(lcnc[k][0])));
        for (std::size_t i = 0; i < width; ++i) {
            const double d = std::abs(lcnc[k][i] - shim[k][i]);
            if (i < integer_channels) {
                if (d != 0 && integer_mismatches++ < 5)
                    fail(cat("period ", std::to_string(k), ": ", integer_names[i], " ", number_text(lcnc[k][i]),
                             " in LinuxCNC, ", number_text(shim[k][i]), " in hal-shim"));
            } else if (!(d <= worst[i])) {  // NaN counts
                worst[i] = d;
                worst_at[i] = k;
            }
        }
    }
    std::cout << "compared " << n << " periods of " << blocks << " blocks, LinuxCNC (halrun, sampler) vs hal-shim"
              << " (firtp-hal), every pin of every period:\n";
    for (int kind = 0; kind < 3; ++kind) {
        std::cout << "  max |difference| " << kinds[kind] << ":";
        for (int a = 0; a < axes; ++a) {
            const std::size_t i = integer_channels + static_cast<std::size_t>(kind * axes + a);
            std::cout << " axis " << a << " " << number_text(worst[i]) << " (period " << worst_at[i] << ")";
            if (!(worst[i] <= tolerance)) fail(cat(kinds[kind], " axis ", std::to_string(a), " differs by ",
                                                  number_text(worst[i]), " > 1e-9"));
        }
        std::cout << "\n";
    }
    std::cout << "  integer pins (tick, current-line, state, done, rejected): "
              << (integer_mismatches ? "DIFFER" : "equal") << "\n";

    // Both end at rest on the program's end point, with every block taken and none refused.
    for (const auto* run : {&lcnc, &shim}) {
        const char* name = run == &lcnc ? "LinuxCNC" : "hal-shim";
        if (run->empty()) continue;
        const std::vector<double>& last = run->back();
        double off = 0, speed = 0;
        for (int a = 0; a < axes; ++a) {
            off = std::max(off, std::abs(last[integer_channels + a] - end[a]));
            speed = std::max(speed, std::abs(last[integer_channels + axes + a]));
        }
        std::cout << "  " << name << " end: |position - program end| " << number_text(off) << " mm, speed "
                  << number_text(speed) << " mm/s, done " << last[3] << ", state " << last[2] << ", rejected "
                  << last[4] << "\n";
        if (!(off <= tolerance) || speed != 0 || last[3] != 1 || last[2] != 0 || last[4] != 0)
            fail(cat(name, " does not end at rest on the program's end point with every block taken"));
    }
    for (const std::string& f : failures) std::cout << "FAIL: " << f << "\n";
    std::cout << (failures.empty() ? "PASS" : "FAIL") << "\n";
    return failures.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        if (args.size() == 4 && args[0] == "prepare") return prepare(args[1], args[2], args[3]);
        if (args.size() == 3 && args[0] == "compare") return compare(args[1], args[2]);
        std::cerr << "usage: firtp-lcnc-hal-run prepare PROGRAM.ngc INI DIR\n"
                     "       firtp-lcnc-hal-run compare DIR SHIM_OUTPUT\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "firtp-lcnc-hal-run: " << e.what() << "\n";
        return 2;
    }
}
