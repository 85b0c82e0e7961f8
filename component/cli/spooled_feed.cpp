#include "spooled_feed.hpp"

#include "plan_run.hpp"

#include <utility>

namespace firtp::cli {

host::ProgramFeed spooled_feed(std::shared_ptr<const ProgramSpool> spool, std::vector<ProgramEvent> events) {
    host::ProgramFeed feed;
    feed.blocks = spool->blocks();
    feed.events = std::move(events);
    feed.read = [spool = std::move(spool)] { return spool->read_blocks(); };
    return feed;
}

host::ProgramFeed read_spooled(const std::filesystem::path& file, const MachineConfig& machine) {
    const std::shared_ptr<ProgramSpool> spool = spool_program(file, machine, AxisVector::Zero());
    std::vector<ProgramEvent> events = std::move(spool->events());
    return spooled_feed(spool, std::move(events));
}

}  // namespace firtp::cli
