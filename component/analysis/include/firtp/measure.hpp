// Measures a sampled trajectory against the programmed path, independently of how it was planned:
// only the samples and the programmed points are used.
#pragma once

#include <firtp/types.hpp>

#include <span>
#include <vector>

namespace firtp {

struct Measured {
    double cycle_time = 0.0;                  // time of the last sample
    std::vector<double> corner_errors;        // per interior programmed point: closest approach to it of the
                                              // path through the samples (straight from sample to sample)
    double max_corner_error = 0.0;
    double max_contour_error = 0.0;           // largest distance of a sample from the programmed polyline
    double max_path_speed = 0.0;              // |velocity| from first differences of positions
    AxisVector max_velocity = AxisVector::Zero();      // per axis, |first difference| / period
    AxisVector max_acceleration = AxisVector::Zero();  // per axis, |second difference| / period^2
    AxisVector max_jerk = AxisVector::Zero();          // per axis, |third difference| / period^3
    AxisVector end_position = AxisVector::Zero();
    bool finite = true;                       // no NaN or inf in any sample
};

// points: the start point followed by the end point of every block (zero-length blocks may repeat
// a point; they are ignored). Samples must be equally spaced by `period`.
Measured measure(std::span<const AxisState> samples, std::span<const AxisVector> points, double period);

}  // namespace firtp
