#include "naive_cam.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace firtp::gcode {

namespace {

// From p to the segment from b to b + m (m not zero), X Y Z: LinuxCNC's arithmetic.
double distance(const AxisVector& p, const Eigen::Vector3d& b, const Eigen::Vector3d& m) {
    const double t = std::clamp(m.dot(p.head<3>() - b) / m.squaredNorm(), 0.0, 1.0);
    return (p.head<3>() - (b + t * m)).norm();
}

}  // namespace

bool extends_chain(std::span<const ChainPoint> chain, const AxisVector& start, const AxisVector& target, double q) {
    if (chain.empty() || chain.size() >= max_chain_points || !(q > 0.0)) return false;
    if (target.tail<6>() != chain.back().at.tail<6>()) return false;  // A B C U V W as they were
    const Eigen::Vector3d b = start.head<3>(), m = target.head<3>() - b;
    if (m.squaredNorm() == 0.0) return false;  // back where it began
    return std::all_of(chain.begin(), chain.end(), [&](const ChainPoint& p) { return distance(p.at, b, m) <= q; });
}

double chain_deviation(std::span<const ChainPoint> chain, const AxisVector& start) {
    if (chain.size() < 2) return 0.0;
    const Eigen::Vector3d b = start.head<3>(), m = chain.back().at.head<3>() - b;
    if (m.squaredNorm() == 0.0) return 0.0;
    double farthest = 0.0;
    for (const ChainPoint& p : chain.first(chain.size() - 1)) farthest = std::max(farthest, distance(p.at, b, m));
    return farthest;
}

std::optional<AxisVector> naive_arc_middle(const AxisVector& start, const AxisVector& end, const Eigen::Vector2d& centre,
                                           bool ccw, double q) {
    if (!(q > 0.0)) return std::nullopt;
    constexpr double turn = 2.0 * std::numbers::pi, nearly_none = 1e-5;  // LinuxCNC's: a sweep this small is a full turn
    const double from = std::atan2(start[1] - centre[1], start[0] - centre[0]);
    const double to = std::atan2(end[1] - centre[1], end[0] - centre[0]);
    double sweep = to - from;
    if (ccw)
        while (sweep <= nearly_none) sweep += turn;
    else
        while (sweep >= -nearly_none) sweep -= turn;
    const double r = std::hypot(start[0] - centre[0], start[1] - centre[1]);
    if (!(r * (1.0 - std::cos(0.5 * sweep)) < q)) return std::nullopt;
    const double middle = from + 0.5 * sweep;
    AxisVector p = 0.5 * (start + end);
    p[0] = centre[0] + r * std::cos(middle);
    p[1] = centre[1] + r * std::sin(middle);
    return p;
}

}  // namespace firtp::gcode
