// The CAM-style programs of data/cam (Fusion 360, FreeCAD, pcb2gcode, CamBam headers and bodies)
// read by firtp against LinuxCNC 2.9's own `rs274 -g` (run here): every canonical move LinuxCNC
// makes is a firtp block ending at the same machine point (arcs: chords on LinuxCNC's circle
// ending at its end point), in the same order. rs274 stands alone as an inch machine, so it gets
// the tool table and parameters converted to inches, and its moves (program units, offsets not
// applied) are turned into machine mm with the offsets it reports.
#include <firtp/gcode.hpp>
#include <firtp/ini.hpp>
#include <firtp/machine.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using firtp::AxisVector;

const fs::path data = fs::path(FIRTP_PROGRAM_DATA) / "cam";

struct Move {
    AxisVector end = AxisVector::Zero();  // machine mm
    bool arc = false;
    double cx = 0.0, cy = 0.0;            // arc centre (XY plane), machine mm
    int line = 0;                         // rs274 -g output line
};

std::vector<double> numbers(const std::string& args) {
    std::vector<double> v;
    std::stringstream in(args);
    for (std::string word; std::getline(in, word, ',');) v.push_back(std::stod(word));
    return v;
}

// A copy of `from` with every number after the letters in `keys` (or every second column of a
// parameter file) divided by 25.4.
void to_inches(const fs::path& from, const fs::path& to, bool parameters) {
    std::ifstream in(from);
    std::ofstream out(to);
    for (std::string line; std::getline(in, line);) {
        if (parameters) {
            std::istringstream words(line);
            int number = 0;
            double value = 0.0;
            if (words >> number >> value) out << number << ' ' << value / 25.4 << '\n';
            continue;
        }
        const std::string body = line.substr(0, line.find(';'));
        std::istringstream words(body);
        for (std::string w; words >> w;) {
            if (w[0] == 'Z' || w[0] == 'D') out << w[0] << std::stod(w.substr(1)) / 25.4 << ' ';
            else out << w << ' ';
        }
        out << '\n';
    }
}

// LinuxCNC's moves for `program`, in machine mm.
std::vector<Move> rs274_moves(const fs::path& program, const fs::path& dir) {
    to_inches(data / "cam.tbl", dir / "inch.tbl", false);
    to_inches(data / "cam.var", dir / "inch.var", true);
    // HOME: rs274's libtooldata maps $HOME/.tool.mmap, which it truncates; runs side by side (and a
    // running LinuxCNC) each keep their own.
    const std::string command = "cd '" + data.string() + "' && HOME='" + dir.string() + "' '" FIRTP_RS274 "' -g -i cam.ini -t '" +
                                (dir / "inch.tbl").string() + "' -v '" + (dir / "inch.var").string() + "' '" +
                                program.string() + "' 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    EXPECT_NE(pipe, nullptr);
    std::string text;
    char buffer[4096];
    while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) text += buffer;
    if (pipe != nullptr) {
        EXPECT_EQ(::pclose(pipe), 0) << text;
    }

    const std::regex call(R"(^\s*(\d+) N\.\.\.\.\. ([A-Z_0-9]+)\((.*)\)\s*$)");
    double scale = 25.4;  // rs274's machine is in inches until the program says otherwise
    AxisVector g5x = AxisVector::Zero(), g92 = AxisVector::Zero(), tool = AxisVector::Zero();
    const auto machine = [&](double x, double y, double z) {
        AxisVector p = AxisVector::Zero();
        p[0] = x * scale, p[1] = y * scale, p[2] = z * scale;
        return AxisVector(p + g92 + g5x + tool);
    };
    std::vector<Move> moves;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (!std::regex_match(line, m, call)) continue;
        const std::string name = m[2];
        const int at = std::stoi(m[1]);
        if (name == "USE_LENGTH_UNITS") scale = m[3] == "CANON_UNITS_INCHES" ? 25.4 : 1.0;
        if (name == "SELECT_PLANE") {
            EXPECT_EQ(m[3], "CANON_PLANE_XY") << "the comparison knows XY arcs only";
        }
        if (name == "COMMENT" || name == "MESSAGE") continue;
        std::string args = m[3];
        std::replace(args.begin(), args.end(), ' ', ',');
        args = std::regex_replace(args, std::regex(",+"), ",");
        if (name == "STRAIGHT_FEED" || name == "STRAIGHT_TRAVERSE" || name == "ARC_FEED" || name == "SET_G5X_OFFSET" ||
            name == "SET_G92_OFFSET" || name == "USE_TOOL_LENGTH_OFFSET") {
            const std::vector<double> v = numbers(args);
            if (name == "SET_G5X_OFFSET") g5x.head<3>() = scale * Eigen::Vector3d(v[1], v[2], v[3]);
            if (name == "SET_G92_OFFSET") g92.head<3>() = scale * Eigen::Vector3d(v[0], v[1], v[2]);
            if (name == "USE_TOOL_LENGTH_OFFSET") tool.head<3>() = scale * Eigen::Vector3d(v[0], v[1], v[2]);
            if (name == "STRAIGHT_FEED" || name == "STRAIGHT_TRAVERSE") moves.push_back({machine(v[0], v[1], v[2]), false, 0, 0, at});
            if (name == "ARC_FEED") {
                const AxisVector c = machine(v[2], v[3], v[5]);
                moves.push_back({machine(v[0], v[1], v[5]), true, c[0], c[1], at});
            }
        }
    }
    return moves;
}

class Rs274Compare : public ::testing::TestWithParam<const char*> {};

TEST_P(Rs274Compare, BlocksFollowLinuxCncsCanonicalMoves) {
    const fs::path program = data / GetParam();
    const firtp::IniFile ini = firtp::IniFile::read(data / "cam.ini");
    const firtp::MachineConfig machine = firtp::load_machine(ini);
    const firtp::Program p = firtp::read_gcode(program, machine);
    const fs::path dir = fs::temp_directory_path() / ("firtp-rs274-compare-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::vector<Move> moves = rs274_moves(program, dir);
    fs::remove_all(dir);
    ASSERT_GT(moves.size(), 5u);

    constexpr double printed = 0.003;  // rs274 prints 4 decimals: 1e-4 in = 0.00254 mm
    AxisVector at = p.start;
    std::size_t b = 0;
    int arcs = 0;
    for (const Move& m : moves) {
        if ((m.end - at).norm() < 1e-6) continue;  // no motion: firtp makes no block
        ASSERT_LT(b, p.blocks.size()) << "rs274 line " << m.line << ": firtp has no block left";
        if (!m.arc) {
            EXPECT_LT((p.blocks[b].target - m.end).norm(), printed) << "rs274 line " << m.line << ", block " << b;
            at = p.blocks[b++].target;
            continue;
        }
        ++arcs;
        const double radius = std::hypot(m.end[0] - m.cx, m.end[1] - m.cy);
        for (;;) {
            ASSERT_LT(b, p.blocks.size()) << "rs274 line " << m.line << ": the arc's chords run out";
            const AxisVector& t = p.blocks[b++].target;
            EXPECT_NEAR(std::hypot(t[0] - m.cx, t[1] - m.cy), radius, printed) << "rs274 line " << m.line;
            if ((t - m.end).norm() < printed) break;
        }
        at = p.blocks[b - 1].target;
    }
    EXPECT_EQ(b, p.blocks.size()) << "firtp has blocks rs274 does not";
    if (std::string(GetParam()) != "pcb2gcode.ngc") {
        EXPECT_GT(arcs, 0);
    }
}

INSTANTIATE_TEST_SUITE_P(CamStyles, Rs274Compare,
                         ::testing::Values("fusion.ngc", "freecad.ngc", "pcb2gcode.ngc", "cambam.ngc"));

}  // namespace
