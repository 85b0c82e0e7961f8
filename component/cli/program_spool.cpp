#include "program_spool.hpp"

#include <firtp/text_cat.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <stdlib.h>
#include <unistd.h>

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

std::runtime_error spool_error(const char* what) {
    return std::runtime_error(cat("the program's temporary file: ", what, ": ", std::strerror(errno)));
}

// Reads the records in order, a few hundred at a time.
class Records {
public:
    Records(int fd, std::size_t count) : fd_(fd), count_(count) {}
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
        const off_t offset = static_cast<off_t>(taken_ * sizeof(Record));
        std::size_t got = 0;
        while (got < want * sizeof(Record)) {
            const ssize_t n = ::pread(fd_, reinterpret_cast<char*>(buffer_.data()) + got, want * sizeof(Record) - got,
                                      offset + static_cast<off_t>(got));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) throw spool_error("cannot read it back");
            got += static_cast<std::size_t>(n);
        }
        at_ = 0;
        filled_ = want;
    }

    int fd_;
    std::size_t count_, taken_ = 0, at_ = 0, filled_ = 0;
    std::array<Record, 256> buffer_;
};

class BlockReader : public BlockPuller {
public:
    BlockReader(int fd, std::size_t count) : records_(fd, count) {}
    bool next(Block& block) override { return records_.next(block); }

private:
    Records records_;
};

// The moving blocks' ends after the start, as moving_points() (plan_run.cpp) picks them.
class PointReader : public PointSource {
public:
    PointReader(int fd, const ProgramSpool& spool)
        : records_(fd, spool.blocks()), size_(spool.points()), scale_(spool.scale()), last_(spool.first_point()) {}
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

ProgramSpool::ProgramSpool(const AxisVector& start) : start_(start), last_(start) {
    scale_ = std::max(scale_, start.cwiseAbs().maxCoeff());
    std::string name = (std::filesystem::temp_directory_path() / "firtp-program-XXXXXX").string();
    const int fd = ::mkstemp(name.data());
    if (fd < 0) throw spool_error("cannot create it");
    ::unlink(name.c_str());  // unnamed from now on: nothing is left behind
    file_ = ::fdopen(fd, "w+b");
    if (file_ == nullptr) {
        ::close(fd);
        throw spool_error("cannot open it");
    }
}

ProgramSpool::~ProgramSpool() { std::fclose(file_); }

void ProgramSpool::block(const Block& block) {
    const Record r = record_of(block);
    // Called from within the interpreter, which must not see an exception: close() reports it.
    if (std::fwrite(&r, sizeof r, 1, file_) != 1 && write_errno_ == 0) write_errno_ = errno != 0 ? errno : EIO;
    ++blocks_;
    const double length = (block.target - last_).norm();
    if (length < min_block_length) return;  // skipped by the planner too
    feed_time_ += length / block.feed;
    last_ = block.target;
    scale_ = std::max(scale_, last_.cwiseAbs().maxCoeff());
    ++points_;
}

void ProgramSpool::close() {
    if (std::fflush(file_) != 0 && write_errno_ == 0) write_errno_ = errno != 0 ? errno : EIO;
    if (write_errno_ != 0) {
        errno = write_errno_;
        throw spool_error("cannot write it");
    }
}

std::unique_ptr<BlockPuller> ProgramSpool::read_blocks() const {
    return std::make_unique<BlockReader>(::fileno(file_), blocks_);
}

std::unique_ptr<PointSource> ProgramSpool::read_points() const {
    return std::make_unique<PointReader>(::fileno(file_), *this);
}

}  // namespace firtp::cli
