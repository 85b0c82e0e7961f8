// firtp plan keeps the program and its corner reports in temporary files (issue 14): what comes
// back must be exactly what the in-memory reader, planner and measurement give.
#include "corner_list.hpp"
#include "program_spool.hpp"

#include <firtp/gcode.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace firtp::cli {
namespace {

// Arcs (many chords), a repeated move (no block), a dwell and a pause that must end the block before it
// in an exact stop, a spindle start between blocks.
const char* const program_text = R"(G21 G90 G64 P0.02 F3000
G1 X10 Y0
G1 X10 Y0
G3 X0 Y10 I-10 J0
M3 S1000
G1 X0 Y20
M0
G4 P0.25
G1 X5 Y25
G2 X15 Y25 I5 J0
G1 X0 Y0
M2
)";

class ProgramFile {
public:
    ProgramFile() : path_(std::filesystem::temp_directory_path() / ("firtp_spool_test_" + std::to_string(::getpid()) + ".ngc")) {
        std::ofstream(path_) << program_text;
    }
    ~ProgramFile() { std::filesystem::remove(path_); }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

void expect_same(const Block& a, const Block& b, std::size_t i) {
    EXPECT_EQ(a.target, b.target) << "block " << i;
    EXPECT_EQ(a.feed, b.feed) << "block " << i;
    EXPECT_EQ(a.termination, b.termination) << "block " << i;
    EXPECT_EQ(a.tolerance, b.tolerance) << "block " << i;
    EXPECT_EQ(a.type, b.type) << "block " << i;
    EXPECT_EQ(a.line, b.line) << "block " << i;
    EXPECT_EQ(a.dwell, b.dwell) << "block " << i;
}

TEST(ProgramSpool, GivesBackTheBlocksEventsAndPointsTheReaderKeepsInMemory) {
    const ProgramFile file;
    const MachineConfig machine = default_machine();
    const Program whole = read_gcode(file.path(), machine);
    ProgramSpool spool(whole.start);
    read_gcode(file.path(), machine, whole.start, spool);
    spool.close();

    ASSERT_GT(whole.blocks.size(), 10u);  // the arcs' chords
    ASSERT_EQ(spool.blocks(), whole.blocks.size());
    const auto blocks = spool.read_blocks();
    std::vector<AxisVector> points{whole.start};
    double feed_time = 0.0;
    bool exact_stop_before_pause = false;
    for (std::size_t i = 0; i < whole.blocks.size(); ++i) {
        Block b;
        ASSERT_TRUE(blocks->next(b));
        expect_same(b, whole.blocks[i], i);
        exact_stop_before_pause = exact_stop_before_pause || (b.line == 6 && b.termination == Termination::exact_stop);
        const double length = (b.target - points.back()).norm();
        if (length < min_block_length) continue;
        feed_time += length / b.feed;
        points.push_back(b.target);
    }
    Block past;
    EXPECT_FALSE(blocks->next(past));
    EXPECT_TRUE(exact_stop_before_pause);  // M0 ended the block before it, held back until then

    ASSERT_EQ(spool.events().size(), whole.events.size());
    for (std::size_t i = 0; i < whole.events.size(); ++i) {
        EXPECT_EQ(spool.events()[i].kind, whole.events[i].kind);
        EXPECT_EQ(spool.events()[i].before_block, whole.events[i].before_block);
        EXPECT_EQ(spool.events()[i].line, whole.events[i].line);
    }

    ASSERT_EQ(spool.points(), points.size());
    EXPECT_EQ(spool.last_point(), points.back());
    EXPECT_EQ(spool.feed_time(), feed_time);
    const auto read = spool.read_points();
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(read->next(), points[i]) << "point " << i;
}

// Planned from the spool and measured on the spooled points: bit for bit the vector's plan and
// the batch measurement.
TEST(ProgramSpool, PlanAndMeasurementFromTheFileEqualThoseFromMemory) {
    const ProgramFile file;
    const MachineConfig machine = default_machine();
    const PlannerParameters parameters = machine.planner_parameters();
    const Program whole = read_gcode(file.path(), machine);
    ProgramSpool spool(whole.start);
    read_gcode(file.path(), machine, whole.start, spool);
    spool.close();

    const Trajectory memory = plan_trajectory(parameters, whole.start, whole.blocks);
    struct Keep : TrajectorySink {
        Trajectory t;
        void sample(const AxisState& s) override { t.samples.push_back(s); }
        void corner(const CornerReport& c) override { t.corners.push_back(c); }
    } keep;
    plan_trajectory(parameters, whole.start, *spool.read_blocks(), keep);
    ASSERT_EQ(keep.t.samples.size(), memory.samples.size());
    for (std::size_t k = 0; k < memory.samples.size(); ++k)
        ASSERT_EQ(keep.t.samples[k].position, memory.samples[k].position) << "sample " << k;
    ASSERT_EQ(keep.t.corners.size(), memory.corners.size());

    std::vector<AxisVector> points{whole.start};
    for (const Block& b : whole.blocks)
        if ((b.target - points.back()).norm() >= min_block_length) points.push_back(b.target);
    const Measured batch = measure(memory.samples, points, parameters.period);
    const auto source = spool.read_points();
    MeasureStream stream(*source, parameters.period);
    for (const AxisState& s : memory.samples) stream.add(s);
    const Measured streamed = stream.finish();
    EXPECT_EQ(streamed.corner_errors, batch.corner_errors);
    EXPECT_EQ(streamed.max_corner_error, batch.max_corner_error);
    EXPECT_EQ(streamed.max_contour_error, batch.max_contour_error);
    EXPECT_EQ(streamed.max_jerk, batch.max_jerk);
    EXPECT_GT(batch.corner_errors.size(), 10u);
}

CornerReport numbered(std::size_t i) {
    CornerReport c;
    c.line = static_cast<std::int64_t>(i) + 1;
    c.point = AxisVector::Constant(0.5 * static_cast<double>(i));
    c.beta = 1e-3 * static_cast<double>(i);
    c.speed_in = 1.0 + static_cast<double>(i);
    c.speed_out = 2.0 + static_cast<double>(i);
    c.epsilon = i % 7 == 0 ? std::numeric_limits<double>::infinity() : 0.01;
    c.predicted_error = 0.005;
    c.exact_stop = i % 5 == 0;
    c.bound = i % 2 == 0 ? CornerBound::feed : CornerBound::tolerance;
    c.axis = static_cast<int>(i % 3);
    c.Tk = 1e-4 * static_cast<double>(i);
    c.Tk_tolerance = 2e-4 * static_cast<double>(i);
    return c;
}

// More corners than the read cache holds, read back by index, in a loop, and after more came.
TEST(CornerList, SpooledReportsAndErrorsComeBackAsTheyWent) {
    CornerList list;
    list.spool();
    constexpr std::size_t count = 700;
    for (std::size_t i = 0; i < count; ++i) {
        list.push_back(numbered(i));
        list.add_error(1e-4 * static_cast<double>(i));
        if (i == 300) {
            EXPECT_EQ(list[10].line, 11);  // read while writing
        }
    }
    list.pair_errors();
    ASSERT_EQ(list.size(), count);
    std::size_t i = 0;
    for (const CornerReport& c : list) {
        const CornerReport want = numbered(i);
        EXPECT_EQ(c.line, want.line);
        EXPECT_EQ(c.point, want.point);
        EXPECT_EQ(c.beta, want.beta);
        EXPECT_EQ(c.speed_in, want.speed_in);
        EXPECT_EQ(c.speed_out, want.speed_out);
        EXPECT_EQ(c.epsilon, want.epsilon);
        EXPECT_EQ(c.exact_stop, want.exact_stop);
        EXPECT_EQ(c.bound, want.bound);
        EXPECT_EQ(c.axis, want.axis);
        EXPECT_EQ(c.Tk, want.Tk);
        EXPECT_EQ(c.Tk_tolerance, want.Tk_tolerance);
        ASSERT_TRUE(list.error(i));
        EXPECT_EQ(*list.error(i), 1e-4 * static_cast<double>(i));
        ++i;
    }
    EXPECT_EQ(i, count);
    EXPECT_EQ(list[count - 1].line, static_cast<std::int64_t>(count));
    EXPECT_EQ(list[3].line, 4);
}

// Errors pair with reports only when the counts agree: otherwise none is shown.
TEST(CornerList, UnequalCountsPairNoError) {
    for (const bool spooled : {false, true}) {
        CornerList list;
        if (spooled) list.spool();
        list.push_back(numbered(0));
        list.push_back(numbered(1));
        list.add_error(0.01);
        list.pair_errors();
        EXPECT_FALSE(list.paired());
        EXPECT_FALSE(list.error(0));
        list.add_error(0.02);
        list.pair_errors();
        ASSERT_TRUE(list.error(1));
        EXPECT_EQ(*list.error(1), 0.02);
        list.clear_errors();
        EXPECT_EQ(list.errors_count(), 0u);
        EXPECT_FALSE(list.error(0));
    }
}

}  // namespace
}  // namespace firtp::cli
