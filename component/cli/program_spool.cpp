#include "program_spool.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

namespace firtp::cli {
namespace {

// One block on disk: every field, fixed layout.
struct Record {
    double target[max_axes];
    double feed, tolerance, dwell;
    std::int64_t line;
    std::int32_t termination, type;
};

Record record_of(const Block& b) {
    Record r{};
    for (Eigen::Index a = 0; a < max_axes; ++a) r.target[a] = b.target[a];
    r.feed = b.feed;
    r.tolerance = b.tolerance;
    r.dwell = b.dwell;
    r.line = b.line;
    r.termination = static_cast<std::int32_t>(b.termination);
    r.type = static_cast<std::int32_t>(b.type);
    return r;
}

Block block_of(const Record& r) {
    Block b;
    for (Eigen::Index a = 0; a < max_axes; ++a) b.target[a] = r.target[a];
    b.feed = r.feed;
    b.tolerance = r.tolerance;
    b.dwell = r.dwell;
    b.line = r.line;
    b.termination = static_cast<Termination>(r.termination);
    b.type = static_cast<MotionType>(r.type);
    return b;
}

// Reads the records in order, a few hundred at a time.
class Records {
public:
    Records(const UnnamedFile& file, std::size_t count) : file_(file), count_(count) {}
    bool next(Block& block) {
        if (taken_ == count_) return false;
        if (at_ == filled_) fill();
        block = block_of(buffer_[at_++]);
        ++taken_;
        return true;
    }

private:
    void fill() {
        const std::size_t want = std::min(buffer_.size(), count_ - taken_);
        file_.read(buffer_.data(), want * sizeof(Record), taken_ * sizeof(Record));
        at_ = 0;
        filled_ = want;
    }

    const UnnamedFile& file_;
    std::size_t count_, taken_ = 0, at_ = 0, filled_ = 0;
    std::array<Record, 256> buffer_;
};

class BlockReader : public BlockPuller {
public:
    BlockReader(const UnnamedFile& file, std::size_t count) : records_(file, count) {}
    bool next(Block& block) override { return records_.next(block); }

private:
    Records records_;
};

// The moving blocks' ends after the start, as moving_points() (plan_run.cpp) picks them.
class PointReader : public PointSource {
public:
    PointReader(const UnnamedFile& file, const ProgramSpool& spool)
        : records_(file, spool.blocks()), size_(spool.points()), scale_(spool.scale()), last_(spool.first_point()) {}
    std::size_t size() const override { return size_; }
    double scale() const override { return scale_; }
    AxisVector next() override {
        if (!first_) {
            first_ = true;
            return last_;
        }
        for (Block b; records_.next(b);)
            if ((b.target - last_).norm() >= min_block_length) return last_ = b.target;
        throw std::logic_error("PointReader: more points asked for than the program has");
    }

private:
    Records records_;
    std::size_t size_;
    double scale_;
    AxisVector last_;
    bool first_ = false;
};

}  // namespace

ProgramSpool::ProgramSpool(const AxisVector& start) : file_("the program"), start_(start), last_(start) {
    scale_ = std::max(scale_, start.cwiseAbs().maxCoeff());
}

void ProgramSpool::block(const Block& block) {
    const Record r = record_of(block);
    // Called from within the interpreter, which must not see an exception: close() reports it.
    if (failed_) return;
    try {
        file_.append(&r, sizeof r);
    } catch (const std::exception&) {
        failed_ = std::current_exception();
        return;
    }
    ++blocks_;
    const double length = (block.target - last_).norm();
    if (length < min_block_length) return;  // skipped by the planner too
    feed_time_ += length / block.feed;
    last_ = block.target;
    scale_ = std::max(scale_, last_.cwiseAbs().maxCoeff());
    ++points_;
}

void ProgramSpool::close() {
    if (failed_) std::rethrow_exception(failed_);
    file_.flush();
}

std::unique_ptr<BlockPuller> ProgramSpool::read_blocks() const {
    return std::make_unique<BlockReader>(file_, blocks_);
}

std::unique_ptr<PointSource> ProgramSpool::read_points() const {
    return std::make_unique<PointReader>(file_, *this);
}

}  // namespace firtp::cli
