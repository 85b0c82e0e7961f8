// firtp-bridge-states: the LCM subscriber of the firtp-lcm-bridge tests.
//
//   firtp-bridge-states record LOG.lcmlog [--url URL]   every message on every channel into an LCM
//                                                      log (lcm::LogFile), until SIGINT/SIGTERM
//   firtp-bridge-states samples LOG.lcmlog OUT.txt [--axes 3]
//       checks the log's FIRTP_AXIS_STATE and FIRTP_STATUS: every message intact (crc), the states'
//       seq 1, 2, ... (from 1 again where the bridge was restarted) and ticks consecutive, no status
//       reporting lost states; writes the states as examples/linuxcnc/record.hal's samples (X Y Z scaled by 2^40, line, 0, 0, at rest), an
//       "overrun" line for every missing period, so that firtp-tp-check measures them; counts the
//       operator controls the states name as applied. Exit 1 on any problem, naming it.
#include <firtp/messages.hpp>

#include <lcm/lcm-cpp.hpp>

#include <cmath>
#include <cstdint>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>

namespace {

volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int) { stop_requested = 1; }

constexpr double position_scale = 1099511627776.0;  // 2^40, as record.hal and firtp-tp-check

int record(const std::string& path, const std::string& url) {
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    const auto lcm = firtp::messages::open(url.empty() ? firtp::messages::default_url() : url);
    lcm::LogFile log(path, "w");
    if (!log.good()) {
        std::cerr << "firtp-bridge-states: cannot write " << path << "\n";
        return 1;
    }
    long events = 0;
    struct Writer {
        lcm::LogFile* log;
        long* events;
        void on(const lcm::ReceiveBuffer* b, const std::string& channel) {
            lcm::LogEvent e{};
            e.eventnum = *events;
            e.timestamp = b->recv_utime;
            e.channel = channel;
            e.datalen = static_cast<int32_t>(b->data_size);
            e.data = b->data;
            log->writeEvent(&e);
            ++*events;
        }
    } writer{&log, &events};
    firtp::messages::keep_everything(lcm->subscribe(".*", &Writer::on, &writer));
    std::cout << "firtp-bridge-states: recording to " << path << std::endl;
    while (!stop_requested) lcm->handleTimeout(20);
    while (lcm->handleTimeout(50) > 0) {}  // what is still queued
    std::cout << "firtp-bridge-states: " << events << " messages recorded" << std::endl;
    return 0;
}

int samples(const std::string& log_path, const std::string& out_path, int axes) {
    lcm::LogFile log(log_path, "r");
    if (!log.good()) {
        std::cerr << "firtp-bridge-states: cannot read " << log_path << "\n";
        return 1;
    }
    std::FILE* out = std::fopen(out_path.c_str(), "w");
    if (!out) {
        std::cerr << "firtp-bridge-states: cannot write " << out_path << "\n";
        return 1;
    }
    long states = 0, statuses = 0, corrupted = 0, seq_gaps = 0, tick_gaps = 0, lost_reported = 0, missing = 0;
    long restarts = 0;  // of the bridge under a running component: seq 1 again, ticks on
    long controls = 0;  // control changes the states name (axis_state_t control_session, control_seq)
    std::int64_t control_session = 0, control_seq = 0;
    std::string last_lost_text;
    std::int64_t last_seq = 0, last_tick = -1, first_tick = -1;
    int last_line = 0;
    std::string first_problem;
    auto problem = [&](const std::string& text) {
        if (first_problem.empty()) first_problem = text;
    };
    for (const lcm::LogEvent* e = log.readNextEvent(); e; e = log.readNextEvent()) {
        if (e->channel == firtp::messages::status_channel) {
            const auto r = firtp::messages::receive<firtp_lcm::status_t>(e->data, static_cast<std::size_t>(e->datalen));
            ++statuses;
            if (r.problem) {
                ++corrupted;
                problem("status: " + *r.problem);
            } else if (r.message.error_code == firtp_lcm::status_t::ERROR_LOST_STATE) {
                ++lost_reported;
                last_lost_text = r.message.error_text;
                problem("status seq " + std::to_string(r.message.seq) + ": " + r.message.error_text);
            }
            continue;
        }
        if (e->channel != firtp::messages::axis_state_channel) continue;
        const auto r = firtp::messages::receive<firtp_lcm::axis_state_t>(e->data, static_cast<std::size_t>(e->datalen));
        if (r.problem) {
            ++corrupted;
            problem("axis state: " + *r.problem);
            continue;
        }
        const firtp_lcm::axis_state_t& m = r.message;
        if (m.seq == 1 && last_seq > 1 && last_tick >= 0 && m.tick == last_tick + 1) {
            ++restarts;  // firtp-lcm-bridge started again, firtp.so ran on: its count starts again
        } else if (m.seq != last_seq + 1) {
            ++seq_gaps;
            problem("axis state seq " + std::to_string(m.seq) + " after " + std::to_string(last_seq));
        }
        last_seq = m.seq;
        if (first_tick < 0) first_tick = m.tick;
        if (last_tick >= 0 && m.tick != last_tick + 1) {
            ++tick_gaps;
            missing += m.tick - last_tick - 1;
            problem("axis state tick " + std::to_string(m.tick) + " after " + std::to_string(last_tick));
            for (std::int64_t t = last_tick + 1; t < m.tick && t - last_tick < 1000000; ++t) std::fputs("overrun\n", out);
        }
        last_tick = m.tick;
        bool at_rest = true;
        for (int a = 0; a < axes; ++a) {
            std::fprintf(out, "%f ", m.position[a] * position_scale);
            at_rest = at_rest && m.velocity[a] == 0.0;
        }
        for (int a = axes; a < 3; ++a) std::fputs("0 ", out);  // firtp-tp-check reads X Y Z
        std::fprintf(out, "%d 0 0 %d\n", m.line, at_rest ? 1 : 0);
        last_line = m.line;
        if (m.control_seq != 0 && (m.control_session != control_session || m.control_seq != control_seq)) ++controls;
        control_session = m.control_session;
        control_seq = m.control_seq;
        ++states;
    }
    std::fclose(out);
    if (states == 0) problem("no FIRTP_AXIS_STATE in the log");
    if (statuses == 0) problem("no FIRTP_STATUS in the log");
    std::printf("controls     %ld named by the states as applied (the last: session %lld seq %lld)\n", controls,
                static_cast<long long>(control_session), static_cast<long long>(control_seq));
    if (restarts > 0) std::printf("restarts     %ld of the bridge (seq from 1 again, ticks consecutive)\n", restarts);
    std::printf("states       %ld (seq 1..%lld, ticks %lld..%lld), last line %d\n", states,
                static_cast<long long>(last_seq), static_cast<long long>(first_tick), static_cast<long long>(last_tick),
                last_line);
    std::printf("gaps         %ld in seq, %ld in ticks (%ld periods missing); %ld corrupted; %ld statuses, %ld "
                "reporting lost states\n",
                seq_gaps, tick_gaps, missing, corrupted, statuses, lost_reported);
    if (!last_lost_text.empty()) std::printf("last report  %s\n", last_lost_text.c_str());
    if (!first_problem.empty()) {
        std::printf("FAIL: %s\n", first_problem.c_str());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "record" && (argc == 3 || (argc == 5 && std::string(argv[3]) == "--url")))
        return record(argv[2], argc == 5 ? argv[4] : "");
    if (command == "samples" && (argc == 4 || (argc == 6 && std::string(argv[4]) == "--axes")))
        return samples(argv[2], argv[3], argc == 6 ? std::stoi(argv[5]) : 3);
    std::cerr << "usage: firtp-bridge-states record LOG [--url URL] | samples LOG OUT [--axes N]\n";
    return 2;
}
