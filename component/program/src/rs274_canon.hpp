// Connects rs274_canon.cpp's canon functions to the reader. Internal to the reader.
#pragma once

#include <string>

namespace firtp::gcode {

class CanonRecorder;

void set_canon_recorder(CanonRecorder* recorder);  // nullptr: none (between programs)
void set_canon_parameter_file(const std::string& path);
void set_canon_axes(int axes);                      // GET_EXTERNAL_AXIS_MASK: X.. the machine's last axis

}  // namespace firtp::gcode
