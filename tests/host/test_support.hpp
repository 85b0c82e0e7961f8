// Shared pieces of the host tests: a fake clock, programs, and the deterministic step loop
// (host step, component tick, 1 ms) on one memq:// LCM. memq delivers a message only to the
// subscriptions that exist when it is published: create the Host before the component's first tick.
#pragma once

#include "fake_component.hpp"

#include <firtp/host.hpp>

#include <chrono>
#include <functional>

namespace firtp::host::test {

using namespace std::chrono_literals;

struct FakeClock {
    Clock::time_point now = Clock::time_point(std::chrono::hours(1));
    void advance(Clock::duration d) { now += d; }
};

inline HostOptions options_for(FakeClock& clock) {
    HostOptions options;
    options.clock = [&clock] { return clock.now; };
    options.program_id = 1000;
    return options;
}

// n moves along X, 1 mm each, line = 10 * seq; `zero_length` seqs repeat the previous point.
inline Program line_program(int n, std::initializer_list<int> zero_length = {}) {
    Program program;
    program.file = "test.ngc";
    double x = 0.0;
    for (int seq = 1; seq <= n; ++seq) {
        if (std::find(zero_length.begin(), zero_length.end(), seq) == zero_length.end()) x += 1.0;
        Block block;
        block.target[0] = x;
        block.feed = 10.0;
        block.tolerance = 0.01;
        block.line = 10 * seq;
        program.blocks.push_back(block);
    }
    return program;
}

// Steps until a final result or max_ticks; `each` runs after every tick (for mid-run actions).
inline Result run_loop(Host& host, FakeComponent& component, FakeClock& clock, int max_ticks = 100000,
                       const std::function<void(int)>& each = {}) {
    for (int tick = 0; tick < max_ticks; ++tick) {
        const Result result = host.step();
        if (result != Result::running) return result;
        component.tick();
        clock.advance(1ms);
        if (each) each(tick);
    }
    return host.result();
}

inline std::vector<std::int64_t> seqs(const std::vector<firtp_lcm::block_t>& blocks) {
    std::vector<std::int64_t> out;
    for (const auto& block : blocks) out.push_back(block.seq);
    return out;
}

inline std::vector<std::int64_t> one_to(std::int64_t n) {
    std::vector<std::int64_t> out;
    for (std::int64_t seq = 1; seq <= n; ++seq) out.push_back(seq);
    return out;
}

}  // namespace firtp::host::test
