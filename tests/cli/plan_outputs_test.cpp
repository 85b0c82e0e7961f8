// firtp plan on the paper's diamond (Section 4): CSV rows, JSON report, overrides, summary.
#include "cli_runner.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cmath>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace firtp::cli_test {
namespace {

using nlohmann::json;

constexpr double paper_cycle_time = 1.2247;  // s, closed form in the paper
constexpr double paper_tk = 0.09634;         // s, each 90 degree corner
constexpr const char* csv_header = "t,x,y,z,feed,vx,vy,vz,ax,ay,az,jx,jy,jz,line";

struct Csv {
    std::string header;
    std::vector<std::vector<double>> rows;
};

Csv parse_csv(const std::string& text) {
    Csv csv;
    std::istringstream lines(text);
    std::getline(lines, csv.header);
    for (std::string line; std::getline(lines, line);) {
        std::vector<double> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        csv.rows.push_back(row);
    }
    return csv;
}

enum Column { t, x, y, z, feed, vx, vy, vz, ax, ay, az, jx, jy, jz, line, columns };

struct DiamondRun {
    TempDir dir;
    Outcome outcome;
    Csv csv;
    json report;

    explicit DiamondRun(std::vector<std::string> flags) {
        std::vector<std::string> args{"plan", example("diamond.ngc").string(), "--csv", (dir / "out.csv").string(),
                                      "--json", (dir / "out.json").string()};
        args.insert(args.end(), flags.begin(), flags.end());
        outcome = run_firtp(args);
        if (outcome.exit_code != 0) return;
        csv = parse_csv(read_file(dir / "out.csv"));
        report = json::parse(read_file(dir / "out.json"));
    }
};

const std::vector<std::string> paper_times{"--t1", "0.148", "--t2", "0.089"};

TEST(PlanOutputs, DiamondCsvRowsRunFromStartToRest) {
    const DiamondRun run(paper_times);
    ASSERT_EQ(run.outcome.exit_code, 0) << run.outcome.err;
    EXPECT_EQ(run.csv.header, csv_header);
    ASSERT_GT(run.csv.rows.size(), 1000u);
    for (const auto& row : run.csv.rows) ASSERT_EQ(row.size(), static_cast<std::size_t>(columns));

    const auto& first = run.csv.rows.front();
    EXPECT_EQ(first[t], 0.0);
    EXPECT_EQ(first[x], 0.0);
    EXPECT_EQ(first[y], 0.0);
    EXPECT_EQ(first[z], 0.0);
    for (std::size_t i = 1; i < run.csv.rows.size(); ++i)
        ASSERT_NEAR(run.csv.rows[i][t] - run.csv.rows[i - 1][t], 0.001, 1e-9) << "row " << i;

    const auto& last = run.csv.rows.back();  // the diamond ends where it started
    EXPECT_NEAR(last[x], 0.0, 1e-9);
    EXPECT_NEAR(last[y], 0.0, 1e-9);
    EXPECT_EQ(last[feed], 0.0);
    EXPECT_DOUBLE_EQ(last[t], run.report["cycle_time_s"].get<double>());

    double top_feed = 0.0;  // the blocks are shorter than T1: the speed peaks near 207 mm/s, never 250
    for (const auto& row : run.csv.rows) top_feed = std::max(top_feed, row[feed]);
    EXPECT_GT(top_feed, 195.0);
    EXPECT_LT(top_feed, 215.0);
}

TEST(PlanOutputs, DiamondJsonMatchesThePaper) {
    const DiamondRun run(paper_times);
    ASSERT_EQ(run.outcome.exit_code, 0) << run.outcome.err;
    const json& r = run.report;
    EXPECT_EQ(r["program"], example("diamond.ngc").string());
    EXPECT_EQ(r["machine"]["stages"], 2);
    EXPECT_EQ(r["machine"]["T_s"], json::array({0.148, 0.089}));
    EXPECT_EQ(r["machine"]["period_s"], 0.001);
    EXPECT_EQ(r["machine"]["tolerance_meaning"], "corner");
    EXPECT_EQ(r["blocks"], 4);

    EXPECT_NEAR(r["cycle_time_s"].get<double>(), paper_cycle_time, 0.01 * paper_cycle_time);
    EXPECT_NEAR(r["closed_form_cycle_time_s"].get<double>(), paper_cycle_time, 1e-3);

    ASSERT_EQ(r["corners"].size(), 3u);
    const std::int64_t lines[] = {5, 6, 7};
    for (std::size_t i = 0; i < 3; ++i) {
        const json& c = r["corners"][i];
        EXPECT_EQ(c["line"], lines[i]);
        EXPECT_NEAR(c["beta_deg"].get<double>(), 90.0, 1e-9);
        EXPECT_EQ(c["epsilon_mm"], 0.5);
        EXPECT_FALSE(c["exact_stop"].get<bool>());
        // The planner keeps a margin for the servo sampling, so Tk sits a little under the paper's.
        EXPECT_LE(c["tk_s"].get<double>(), paper_tk + 1e-5);
        EXPECT_GE(c["tk_s"].get<double>(), paper_tk - 1e-3);
        EXPECT_LE(c["predicted_error_mm"].get<double>(), 0.5);
        EXPECT_LE(c["measured_error_mm"].get<double>(), 0.5);
        EXPECT_GT(c["measured_error_mm"].get<double>(), 0.45);  // the tolerance is used, not wasted
    }
    EXPECT_EQ(r["corners"][1]["point"], json::array({50.0, 0.0, 0.0}));

    const json& m = r["measured"];
    EXPECT_LE(m["max_corner_error_mm"].get<double>(), 0.5);
    EXPECT_LT(m["max_contour_error_mm"].get<double>(), m["max_corner_error_mm"].get<double>());
    EXPECT_LT(m["end_error_mm"].get<double>(), 1e-9);
    EXPECT_EQ(m["max_axis_acceleration"].size(), 3u);
    EXPECT_EQ(m["max_axis_jerk"][2], 0.0);
}

// Third differences multiply rounding by 1/period^3 = 1e9: only round-trip digits reproduce the jerk.
TEST(PlanOutputs, CsvPositionsRoundTrip) {
    const DiamondRun run(paper_times);
    ASSERT_EQ(run.outcome.exit_code, 0) << run.outcome.err;
    const auto& rows = run.csv.rows;
    double jerk = 0.0;
    for (std::size_t i = 1; i + 2 < rows.size(); ++i)
        jerk = std::max(jerk, std::abs(rows[i + 2][x] - 3.0 * rows[i + 1][x] + 3.0 * rows[i][x] - rows[i - 1][x]));
    jerk /= 0.001 * 0.001 * 0.001;
    const double reported = run.report["measured"]["max_axis_jerk"][0].get<double>();
    EXPECT_NEAR(jerk, reported, 1e-9 * reported);
}

TEST(PlanOutputs, IniGivesTheSameAsFlags) {
    const DiamondRun flags(paper_times);
    const DiamondRun ini({"--ini", example("diamond.ini").string()});
    ASSERT_EQ(flags.outcome.exit_code, 0) << flags.outcome.err;
    ASSERT_EQ(ini.outcome.exit_code, 0) << ini.outcome.err;
    EXPECT_EQ(ini.report["machine"]["T_s"], flags.report["machine"]["T_s"]);
    EXPECT_EQ(ini.report["cycle_time_s"], flags.report["cycle_time_s"]);
    EXPECT_EQ(ini.report["corners"], flags.report["corners"]);
    EXPECT_EQ(ini.csv.rows.size(), flags.csv.rows.size());
}

TEST(PlanOutputs, ContourToleranceAllowsMoreOverlap) {
    const DiamondRun corner(paper_times);
    std::vector<std::string> flags = paper_times;
    flags.insert(flags.end(), {"--tolerance-meaning", "contour"});
    const DiamondRun contour(flags);
    ASSERT_EQ(contour.outcome.exit_code, 0) << contour.outcome.err;
    EXPECT_EQ(contour.report["machine"]["tolerance_meaning"], "contour");
    EXPECT_GT(contour.report["corners"][0]["tk_s"].get<double>(), corner.report["corners"][0]["tk_s"].get<double>());
    EXPECT_LT(contour.report["cycle_time_s"].get<double>(), corner.report["cycle_time_s"].get<double>());
    EXPECT_LE(contour.report["measured"]["max_contour_error_mm"].get<double>(), 0.5 + 1e-6);
}

TEST(PlanOutputs, PeriodAndToleranceOverrides) {
    TempDir dir;
    // G64 without P takes the machine's tolerance, which --tolerance sets.
    write_file(dir / "square.ngc", "G21 G90 G64\nF6000\nG1 X20\nG1 Y20\nG1 X0\nM2\n");
    const Outcome r = run_firtp({"plan", (dir / "square.ngc").string(), "--period", "0.002", "--tolerance", "0.02",
                                 "--csv", (dir / "out.csv").string(), "--json", (dir / "out.json").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Csv csv = parse_csv(read_file(dir / "out.csv"));
    for (std::size_t i = 1; i < csv.rows.size(); ++i) ASSERT_NEAR(csv.rows[i][t] - csv.rows[i - 1][t], 0.002, 1e-9);
    const json report = json::parse(read_file(dir / "out.json"));
    EXPECT_EQ(report["machine"]["period_s"], 0.002);
    EXPECT_EQ(report["machine"]["default_tolerance_mm"], 0.02);
    ASSERT_EQ(report["corners"].size(), 2u);
    for (const json& c : report["corners"]) EXPECT_EQ(c["epsilon_mm"], 0.02);
}

// Exact stops in the paper's chain: Tk = 0, each stop waits for the next servo sample, the end is
// rounded up to one.
TEST(PlanOutputs, ExactStopClosedFormCycleTime) {
    TempDir dir;
    write_file(dir / "stops.ngc", "G21 G90 G61\nF3000\nG1 X10\nG1 X10 Y7.3\nG1 X0 Y0\nM2\n");
    const Outcome r = run_firtp({"plan", (dir / "stops.ngc").string(), "--t1", "0.06", "--t2", "0.05", "--json",
                                 (dir / "out.json").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json report = json::parse(read_file(dir / "out.json"));
    ASSERT_EQ(report["corners"].size(), 2u);
    for (const json& c : report["corners"]) {
        EXPECT_TRUE(c["exact_stop"].get<bool>());
        EXPECT_EQ(c["tk_s"], 0.0);
        EXPECT_LT(c["measured_error_mm"].get<double>(), 1e-9);
    }
    const double td = report["machine"]["delay_s"].get<double>();
    const double tv_sum = (10.0 + 7.3 + std::hypot(10.0, 7.3)) / 50.0;
    const double closed = report["closed_form_cycle_time_s"].get<double>();
    EXPECT_NEAR(closed, tv_sum + 3.0 * td, 1e-12);
    EXPECT_GE(report["cycle_time_s"].get<double>(), closed - 1e-9);
    EXPECT_LE(report["cycle_time_s"].get<double>(), closed + 3 * 0.001 + 1e-9);
}

// Exact stops smoothed at the limits: each move is a pulse whose two steps use the acceleration of
// its most loaded axis (T1 = F max|u_a| / A) and the jerk time T2 = A / J; a move lasts at most
// Tv + T1 + T2 and the next starts before the last one has quite stopped (their T2 stages overlap).
TEST(PlanOutputs, ExactStopsAtTheLimits) {
    TempDir dir;
    write_file(dir / "stops.ngc", "G21 G90 G61\nF3000\nG1 X10\nG1 X10 Y7.3\nG1 X0 Y0\nM2\n");
    const Outcome r = run_firtp({"plan", (dir / "stops.ngc").string(), "--json", (dir / "out.json").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json report = json::parse(read_file(dir / "out.json"));
    EXPECT_EQ(report["machine"]["smoothing"], "limits");
    EXPECT_TRUE(report["closed_form_cycle_time_s"].is_null());
    ASSERT_EQ(report["corners"].size(), 2u);
    for (const json& c : report["corners"]) {
        EXPECT_TRUE(c["exact_stop"].get<bool>());
        EXPECT_EQ(c["bound"], "exact stop");
        EXPECT_EQ(c["speed_out_mm_s"], 0.0);
        EXPECT_LT(c["measured_error_mm"].get<double>(), 1e-9);
    }
    const double f = 50.0, a = 5000.0, t2 = 0.05;  // the built-in machine: 5000 mm/s^2, 1e5 mm/s^3
    const double diagonal = std::hypot(10.0, 7.3);
    const double moves[][2] = {{10.0, 1.0}, {7.3, 1.0}, {diagonal, 10.0 / diagonal}};  // length, max |u_a|
    double tv = 0.0, separate = 0.0;
    for (const auto& m : moves) {
        tv += m[0] / f;
        separate += m[0] / f + f * m[1] / a + t2;
    }
    EXPECT_NEAR(report["feed_time_s"].get<double>(), tv, 1e-12);
    EXPECT_GT(report["cycle_time_s"].get<double>(), tv);
    EXPECT_LE(report["cycle_time_s"].get<double>(), separate + 0.001);
}

TEST(PlanOutputs, SummaryOnStdout) {
    const DiamondRun run(paper_times);
    ASSERT_EQ(run.outcome.exit_code, 0) << run.outcome.err;
    const std::string& out = run.outcome.out;
    for (const char* part : {"diamond.ngc", "4 moving, 3 corners", "cycle time   1.22", "closed form 1.224",
                             "tolerance 0.5000 mm", "all within tolerance", "max acceleration", "jerk", "out.csv"})
        EXPECT_NE(out.find(part), std::string::npos) << part << " missing from\n" << out;
    EXPECT_TRUE(run.outcome.err.empty()) << run.outcome.err;
}

TEST(PlanOutputs, ReplacesAnExistingFileAndLeavesNoTemporaries) {
    TempDir dir;
    write_file(dir / "out.csv", "old contents\n");
    const Outcome r = run_firtp({"plan", example("corner90.ngc").string(), "--csv", (dir / "out.csv").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_file(dir / "out.csv").rfind(csv_header, 0), 0u);
    EXPECT_EQ(dir.names(), std::set<std::string>{"out.csv"});
}

}  // namespace
}  // namespace firtp::cli_test

namespace firtp::cli_test {
namespace {

// The JSON is written a corner at a time; it must read back as the very text one JSON document's
// dump(2) gives (what firtp wrote before it streamed): with corners, with the paper's Tk fields,
// and with none.
TEST(PlanOutputs, StreamedJsonIsTheDocumentsOwnDump) {
    for (const std::vector<std::string>& program :
         {std::vector<std::string>{example("steps.ngc").string()},
          std::vector<std::string>{example("diamond.ngc").string(), "--t1", "0.148", "--t2", "0.089"}}) {
        TempDir dir;
        std::vector<std::string> args{"plan"};
        args.insert(args.end(), program.begin(), program.end());
        args.insert(args.end(), {"--json", (dir / "out.json").string()});
        ASSERT_EQ(run_firtp(args).exit_code, 0);
        const std::string text = read_file(dir / "out.json");
        const json report = json::parse(text);
        EXPECT_GT(report["corners"].size(), 2u);
        EXPECT_EQ(text, report.dump(2) + "\n") << program[0];
    }
    TempDir dir;
    write_file(dir / "line.ngc", "G1 X10 F600\nM2\n");
    ASSERT_EQ(run_firtp({"plan", (dir / "line.ngc").string(), "--json", (dir / "out.json").string()}).exit_code, 0);
    const std::string text = read_file(dir / "out.json");
    EXPECT_EQ(json::parse(text)["corners"], json::array());
    EXPECT_EQ(text, json::parse(text).dump(2) + "\n");
}

// An output that is not a file is written in place: `--csv /dev/null` used to rename a temporary
// onto /dev/null and so replace the device with a file. A pipe stands in for the device here.
TEST(PlanOutputs, CsvIntoAPipeIsWrittenInPlace) {
    TempDir dir;
    const std::filesystem::path fifo = dir / "samples.fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::atomic<bool> done{false};
    Outcome outcome;
    std::thread plan([&] {
        outcome = run_firtp({"plan", example("diamond.ngc").string(), "--csv", fifo.string()});
        done = true;
    });
    const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    std::string received;
    char buffer[1 << 16];
    for (bool last = false;;) {  // until firtp has exited and the pipe is empty
        pollfd p{fd, POLLIN, 0};
        ::poll(&p, 1, 50);
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            received.append(buffer, static_cast<std::size_t>(n));
            continue;
        }
        if (last) break;
        last = done;
    }
    plan.join();
    ::close(fd);
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
    EXPECT_EQ(dir.names(), std::set<std::string>{"samples.fifo"});  // no temporary beside it
    const Outcome file = run_firtp({"plan", example("diamond.ngc").string(), "--csv", (dir / "samples.csv").string()});
    ASSERT_EQ(file.exit_code, 0) << file.err;
    EXPECT_GT(received.size(), 10000u);
    EXPECT_EQ(received, read_file(dir / "samples.csv"));
}

// Through a symbolic link the file it names is written; the link stays.
TEST(PlanOutputs, CsvThroughASymbolicLinkReplacesTheFileItNames) {
    TempDir dir;
    std::filesystem::create_directory(dir / "data");
    write_file(dir / "data" / "samples.csv", "old\n");
    std::filesystem::create_symlink("data/samples.csv", dir / "latest.csv");
    const Outcome outcome = run_firtp({"plan", example("diamond.ngc").string(), "--csv", (dir / "latest.csv").string()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "latest.csv"));
    EXPECT_EQ(read_file(dir / "data" / "samples.csv").rfind("t,x,y,z,", 0), 0u);
    EXPECT_EQ(dir.names(), (std::set<std::string>{"data", "latest.csv"}));
}

}  // namespace
}  // namespace firtp::cli_test
