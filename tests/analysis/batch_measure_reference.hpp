// The measurement as one pass over all samples, before it was streamed (test oracle only).
#pragma once

#include <firtp/measure.hpp>

namespace firtp::reference {

Measured measure_batch(std::span<const AxisState> samples, std::span<const AxisVector> points, double period);

}  // namespace firtp::reference
