#include "path_points.hpp"

namespace firtp::cli {

void PathPoints::for_each(const std::function<void(std::size_t, const AxisVector&)>& f) const {
    if (!spool_) {
        for (std::size_t i = 0; i < kept_.size(); ++i) f(i, kept_[i]);
        return;
    }
    const std::unique_ptr<PointSource> points = read();
    for (std::size_t i = 0; i < points->size(); ++i) f(i, points->next());
}

}  // namespace firtp::cli
