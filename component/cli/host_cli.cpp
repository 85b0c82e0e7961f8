#include "component_options.hpp"
#include "csv_writer.hpp"
#include "output_files.hpp"
#include "plan_run.hpp"
#include <firtp/recorded_states.hpp>
#include "run_command.hpp"
#include "spooled_feed.hpp"

#include <firtp/host_command.hpp>

#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

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
    h.read_program = [&h] { return read_spooled(h.program, h.machine); };
    h.url = options.lcm_url;
    h.host.max_feed_scale = options.max_feed;
    if (options.plan.csv) {
        // Each axis state to its CSV row as it arrives; the file in place at the end.
        struct Recording {
            OutputFiles files;
            std::ofstream out;
            std::optional<CsvWriter> rows;
            std::optional<AxisStateSamples> samples;
        };
        const auto recording = std::make_shared<Recording>();
        const std::filesystem::path csv = *options.plan.csv;
        recording->out.open(recording->files.create(csv), std::ios::binary);
        recording->rows.emplace(recording->out);
        recording->samples.emplace(h.machine.period, [rows = &*recording->rows](const AxisState& s) { rows->row(s); });
        h.record_axis_state = [recording](const firtp_lcm::axis_state_t& m) { recording->samples->add(m); };
        h.axis_states_done = [recording, csv] {
            recording->samples->finish();
            recording->out.close();
            if (!recording->out) throw std::runtime_error("cannot write '" + csv.string() + "'");
            recording->files.commit();
        };
    }
    return host::run_host_command(h);
}

}  // namespace firtp::cli
