// A program read once through LinuxCNC's interpreter into an unnamed temporary file (TMPDIR, 112
// bytes a block, gone when the process ends however it ends), so that `firtp plan` needs memory
// for the planner's queue and the measurement's window, not for the program: the blocks are read
// back as the planner takes them, the points as the measurement reaches them. Reading first, in
// full, keeps today's guarantee: a G-code error anywhere is reported before any planning or
// output, and the interpreter runs the program once.
#pragma once

#include "record_file.hpp"

#include <firtp/gcode.hpp>
#include <firtp/measure.hpp>
#include <firtp/trajectory.hpp>

#include <cstddef>
#include <exception>
#include <memory>
#include <vector>

namespace firtp::cli {

class ProgramSpool : public ProgramSink {
public:
    explicit ProgramSpool(const AxisVector& start);  // throws std::runtime_error: no temporary file

    void block(const Block& block) override;
    void event(const ProgramEvent& event) override { events_.push_back(event); }
    void joined(const JoinedMoves& joined) override { joined_ = joined; }
    const JoinedMoves& joined() const { return joined_; }
    // Every block written: readers may start. Throws std::runtime_error when a write failed.
    void close();

    std::size_t blocks() const { return blocks_; }
    std::vector<ProgramEvent>& events() { return events_; }  // few: kept in memory

    // The path's points: the start, then the end of every block that moves (as the planner skips
    // zero-length ones).
    std::size_t points() const { return points_; }
    const AxisVector& first_point() const { return start_; }
    const AxisVector& last_point() const { return last_; }
    double scale() const { return scale_; }          // max(1, largest |coordinate| of a point)
    double feed_time() const { return feed_time_; }  // sum over the moving blocks of length / feed

    std::unique_ptr<BlockPuller> read_blocks() const;  // each an independent reader from the start
    std::unique_ptr<PointSource> read_points() const;

private:
    UnnamedFile file_;
    std::exception_ptr failed_;  // the first write that failed
    AxisVector start_, last_;
    std::size_t blocks_ = 0, points_ = 1;
    double scale_ = 1.0, feed_time_ = 0.0;
    std::vector<ProgramEvent> events_;
    JoinedMoves joined_;
};

}  // namespace firtp::cli
