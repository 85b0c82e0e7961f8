// The sampled trajectory as CSV, one row per servo period.
#pragma once

#include <firtp/types.hpp>

#include <ostream>
#include <span>

namespace firtp::cli {

// Header t,x,y,z,feed,vx,vy,vz,ax,ay,az,jx,jy,jz,line; feed = |v| over X Y Z.
void write_csv(std::ostream& out, std::span<const AxisState> samples);

}  // namespace firtp::cli
