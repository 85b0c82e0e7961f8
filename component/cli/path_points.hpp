// The programmed path's points: the start, then the end of every block that moves. Kept in memory,
// or only summarised while a ProgramSpool holds them (`firtp plan`: memory not growing with the
// program).
#pragma once

#include "program_spool.hpp"

#include <firtp/types.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace firtp::cli {

class PathPoints {
public:
    PathPoints() = default;
    PathPoints(std::vector<AxisVector> points) : kept_(std::move(points)) {}  // NOLINT: a vector is the points
    PathPoints(std::initializer_list<AxisVector> points) : kept_(points) {}
    explicit PathPoints(std::shared_ptr<const ProgramSpool> spool) : spool_(std::move(spool)) {}

    std::size_t size() const { return spool_ ? spool_->points() : kept_.size(); }
    bool empty() const { return size() == 0; }
    const AxisVector& front() const { return spool_ ? spool_->first_point() : kept_.front(); }
    const AxisVector& back() const { return spool_ ? spool_->last_point() : kept_.back(); }

    bool spooled() const { return spool_ != nullptr; }
    std::span<const AxisVector> kept() const { return kept_; }  // empty when spooled
    std::unique_ptr<PointSource> read() const { return spool_->read_points(); }  // spooled only
    // Every point in order, with its index.
    void for_each(const std::function<void(std::size_t, const AxisVector&)>& f) const;

private:
    std::vector<AxisVector> kept_;
    std::shared_ptr<const ProgramSpool> spool_;
};

}  // namespace firtp::cli
