// G-code reader for the LinuxCNC (RS274NGC) dialect, the subset firtp plans so far:
// G0 G1 with X Y Z, F (units/min), G20/G21, G90/G91, G17, G61/G61.1 (exact stop), G64 [P tol],
// N words, ( ) and ; comments, M2/M30, a '%' line. Anything else is an error that names
// file:line:column and what is wrong; nothing is returned then.
#pragma once

#include <firtp/machine.hpp>
#include <firtp/types.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace firtp {

class GcodeError : public std::runtime_error {
public:
    GcodeError(std::string file, int line, int column, const std::string& message);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    int column() const { return column_; }

private:
    std::string file_;
    int line_;
    int column_;
};

struct Program {
    std::string file;
    AxisVector start = AxisVector::Zero();  // machine position before the first block
    std::vector<Block> blocks;              // machine units (mm), feed in mm/s, line = source line
};

// Feeds are capped as LinuxCNC does: by [TRAJ]MAX_LINEAR_VELOCITY and by each axis' MAX_VELOCITY
// along the move's direction; G0 runs at that cap (the machine's rapid velocity).
// G64 without P uses machine.default_tolerance; G64 P0 means no tolerance (+inf, full overlap).
Program parse_gcode(std::string_view text, const std::string& file_name, const MachineConfig& machine,
                    const AxisVector& start = AxisVector::Zero());
Program read_gcode(const std::filesystem::path& path, const MachineConfig& machine,
                   const AxisVector& start = AxisVector::Zero());

}  // namespace firtp
