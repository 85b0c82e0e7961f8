#include "move_speed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp::gcode {
namespace {

double squares(const AxisVector& d, Eigen::Index first, Eigen::Index count) {
    double sum = 0.0;
    for (Eigen::Index a = first; a < first + count; ++a) sum += d[a] * d[a];
    return sum;
}

}  // namespace

MoveLengths move_lengths(const AxisVector& d) {
    const double xyz = squares(d, 0, 3), abc = squares(d, 3, 3), uvw = squares(d, 6, 3);
    return {std::sqrt(xyz), std::sqrt(abc), std::sqrt(uvw), std::sqrt(xyz + abc + uvw)};
}

double MoveLengths::feed_length() const {
    if (xyz > zero_length) return xyz;
    if (uvw > zero_length) return uvw;
    return abc;
}

bool MoveLengths::linear() const { return xyz > zero_length || uvw > zero_length; }

double speed_cap(const AxisVector& delta, double path, bool linear, const MachineLimits& limits) {
    double cap = std::numeric_limits<double>::infinity();
    if (linear && limits.max_linear_velocity > 0.0) cap = limits.max_linear_velocity;
    for (int a = 0; a < std::min(limits.axes, max_axes); ++a) {
        const double v = limits.axis[a].max_velocity;
        const double d = std::abs(delta[a]);
        if (d > 0.0 && v > 0.0) cap = std::min(cap, v * path / d);
    }
    return cap;
}

}  // namespace firtp::gcode
