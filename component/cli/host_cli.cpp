#include "component_options.hpp"
#include "csv_writer.hpp"
#include "output_files.hpp"
#include "plan_run.hpp"
#include <firtp/recorded_states.hpp>
#include "run_command.hpp"

#include <firtp/host_command.hpp>

#include <iostream>

namespace firtp::cli {

int host_command(std::span<const std::string> args) {
    const ComponentOptions options = parse_host_options(args);
    if (options.plan.help) {
        std::cout << host_help();
        return 0;
    }
    host::HostCommandOptions h;
    h.program = options.plan.program;
    h.machine = load_machine_config(options.plan);
    h.url = options.lcm_url;
    h.host.max_feed_scale = options.max_feed;
    if (options.plan.csv) {
        h.host.record_axis_states = true;
        const std::filesystem::path csv = *options.plan.csv;
        const double period = h.machine.period;
        h.save_axis_states = [csv, period](const std::vector<firtp_lcm::axis_state_t>& states) {
            OutputFiles outputs;
            outputs.write(csv, [&](std::ostream& out) { write_csv(out, firtp::samples_from_axis_states(states, period)); });
            outputs.commit();
        };
    }
    return host::run_host_command(h);
}

}  // namespace firtp::cli
