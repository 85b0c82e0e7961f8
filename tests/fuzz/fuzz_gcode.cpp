// libFuzzer target: the G-code reader (parse_gcode) on any text, on three machines.
// Any input either gives a GcodeError (file:line:column) or a program whose every block can be
// planned: finite target, feed > 0 and finite, a blend's tolerance > 0 (or +inf), line within
// the text.
// Anything else (another exception, a crash, undefined behaviour, a leak, a hang) is a finding.
#include <firtp/gcode.hpp>
#include <firtp/machine.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "require.hpp"

namespace {

firtp::MachineConfig machine(std::uint8_t choice) {
    firtp::MachineConfig m = firtp::default_machine();
    m.max_program_blocks = 20000;  // bounds every input: a loop that never moves ends after as many lines
    if (choice % 3 == 1) {  // five axes X Y Z A B with limits, coarser chords
        m.limits.axes = 5;
        for (int a = 3; a < 5; ++a) m.limits.axis[a] = {3600.0, 36000.0, 1e6};
        m.arc_chord_tolerance = 0.01;
    } else if (choice % 3 == 2) {  // no limits: the reader's caps are off
        m.limits = firtp::MachineLimits{};
        m.given_times = {0.148, 0.089};
    }
    return m;
}


}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const firtp::MachineConfig machines[3] = {machine(0), machine(1), machine(2)};
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    const firtp::MachineConfig& m = machines[data[0] % 3];
    try {
        const firtp::Program p = firtp::parse_gcode(text, "fuzz.ngc", m);
        std::int64_t lines = 1;
        for (char c : text) lines += c == '\n';
        for (const firtp::Block& b : p.blocks) {
            require(b.target.allFinite());
            require(std::isfinite(b.feed) && b.feed > 0.0);
            require(b.termination == firtp::Termination::exact_stop || b.tolerance > 0.0);  // +inf: G64 P0
            require(b.line >= 1 && b.line <= lines);
        }
    } catch (const firtp::GcodeError& e) {
        require(e.line() >= 0 && e.column() >= 0);
    }
    return 0;
}
