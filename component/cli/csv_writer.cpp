#include "csv_writer.hpp"

#include "number_text.hpp"

#include <charconv>

namespace firtp::cli {

CsvWriter::CsvWriter(std::ostream& out) : out_(out) { out_ << "t,x,y,z,feed,vx,vy,vz,ax,ay,az,jx,jy,jz,line\n"; }

void CsvWriter::row(const AxisState& s) {
    row_.clear();
    const auto xyz = [&](const AxisVector& v) {
        for (int a = 0; a < 3; ++a) {
            row_ += ',';
            append_number(row_, v[a]);
        }
    };
    append_number(row_, s.time);
    xyz(s.position);
    row_ += ',';
    append_number(row_, s.velocity.head<3>().norm());
    xyz(s.velocity);
    xyz(s.acceleration);
    xyz(s.jerk);
    row_ += ',';
    char line[24];
    row_.append(line, std::to_chars(line, line + sizeof line, s.line).ptr);
    row_ += '\n';
    out_ << row_;
}

void write_csv(std::ostream& out, std::span<const AxisState> samples) {
    CsvWriter csv(out);
    for (const AxisState& s : samples) csv.row(s);
}

}  // namespace firtp::cli
