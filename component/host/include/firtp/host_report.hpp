// The report `firtp host` prints when a program ends.
#pragma once

#include <firtp/host.hpp>

#include <string>

namespace firtp::host {

// Several lines, e.g.
//   firtp host: part.ngc: done in 12.3 s
//     blocks: 120, acknowledged 120, executed 120; published 122 (2 go-backs), refused 2
//     axis states: 12034 received
//     corrupted in transit (CRC mismatch): 3 blocks and controls refused by the component, 1 statuses and axis states dropped here
// (that line only when there were any), plus "  error: ..." lines for a failure or an incomplete
// axis-state recording.
std::string host_report(const std::string& program_file, const Host& host, Result result, double seconds,
                        bool recorded_axis_states);

}  // namespace firtp::host
