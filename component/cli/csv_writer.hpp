// The sampled trajectory as CSV, one row per servo period.
#pragma once

#include <firtp/types.hpp>

#include <ostream>
#include <span>
#include <string>

namespace firtp::cli {

// Header t,x,y,z,feed,vx,vy,vz,ax,ay,az,jx,jy,jz,line; feed = |v| over X Y Z. Writes the header on
// construction and one row per row() call, as the samples are made.
class CsvWriter {
public:
    explicit CsvWriter(std::ostream& out);
    void row(const AxisState& s);

private:
    std::ostream& out_;
    std::string row_;
};

void write_csv(std::ostream& out, std::span<const AxisState> samples);

}  // namespace firtp::cli
