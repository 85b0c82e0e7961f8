#include <firtp/host_report.hpp>

#include <cstdio>

namespace firtp::host {

std::string host_report(const std::string& program_file, const Host& host, Result result, double seconds,
                        bool recorded_axis_states) {
    const Progress p = host.progress();
    const Statistics s = host.statistics();
    char line[300];
    std::string text;
    std::snprintf(line, sizeof line, "firtp host: %s: %s in %.1f s\n", program_file.c_str(),
                  result == Result::running ? "quit before the component confirmed the abort" : to_string(result),
                  seconds);
    text += line;
    std::snprintf(line, sizeof line,
                  "  blocks: %zu, acknowledged %zu, executed %zu; published %lld (%lld go-backs), refused %lld\n",
                  p.blocks, p.acknowledged, p.executed, static_cast<long long>(s.blocks_published),
                  static_cast<long long>(s.go_backs), static_cast<long long>(s.rejected));
    text += line;
    if (s.events_published > 0) {
        std::snprintf(line, sizeof line, "  events: published %lld, reached %lld\n",
                      static_cast<long long>(s.events_published), static_cast<long long>(s.events_reached));
        text += line;
    }
    std::snprintf(line, sizeof line, "  axis states: %lld received\n", static_cast<long long>(s.axis_states));
    text += line;
    if (s.corrupted_refused > 0 || s.corrupted_dropped > 0) {
        std::snprintf(line, sizeof line,
                      "  corrupted in transit (CRC mismatch): %lld blocks and controls refused by the component, "
                      "%lld statuses and axis states dropped here\n",
                      static_cast<long long>(s.corrupted_refused), static_cast<long long>(s.corrupted_dropped));
        text += line;
    }
    if (!host.error().empty()) text += "  error: " + host.error() + "\n";
    const std::string gaps = host.axis_state_gap_text();
    if (recorded_axis_states && !gaps.empty()) text += "  error: recording incomplete: " + gaps + "\n";
    return text;
}

}  // namespace firtp::host
