// A program in a ProgramSpool as the host sends it: its blocks read back from the temporary file
// as flow control lets them go (`firtp run` and `firtp host`: memory not growing with the program).
#pragma once

#include "program_spool.hpp"

#include <firtp/host.hpp>
#include <firtp/machine.hpp>

#include <filesystem>
#include <memory>
#include <vector>

namespace firtp::cli {

host::ProgramFeed spooled_feed(std::shared_ptr<const ProgramSpool> spool, std::vector<ProgramEvent> events);

// Reads `file` through LinuxCNC's interpreter into a spool, for the host (throws GcodeError).
host::ProgramFeed read_spooled(const std::filesystem::path& file, const MachineConfig& machine);

}  // namespace firtp::cli
