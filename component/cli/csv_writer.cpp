#include "csv_writer.hpp"

#include "number_text.hpp"

#include <charconv>
#include <string>

namespace firtp::cli {

void write_csv(std::ostream& out, std::span<const AxisState> samples) {
    out << "t,x,y,z,feed,vx,vy,vz,ax,ay,az,jx,jy,jz,line\n";
    std::string row;
    for (const AxisState& s : samples) {
        row.clear();
        const auto xyz = [&](const AxisVector& v) {
            for (int a = 0; a < 3; ++a) {
                row += ',';
                append_number(row, v[a]);
            }
        };
        append_number(row, s.time);
        xyz(s.position);
        row += ',';
        append_number(row, s.velocity.head<3>().norm());
        xyz(s.velocity);
        xyz(s.acceleration);
        xyz(s.jerk);
        row += ',';
        char line[24];
        row.append(line, std::to_chars(line, line + sizeof line, s.line).ptr);
        row += '\n';
        out << row;
    }
}

}  // namespace firtp::cli
