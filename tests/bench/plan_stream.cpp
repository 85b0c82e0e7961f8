// Offline planning in constant memory, and the cost of planning one block.
//
//   firtp_plan_stream --generate spiral|random|corners [--blocks 1000000] [--seed 1] [--ini FILE] [--json]
//                     [--max-growth-kib K] [--slowest N] [--per-period K] [--batch]
//   firtp_plan_stream --program FILE.ngc [--ini FILE] [--json] [--slowest N] [--per-period K] [--batch]
//
// Plans and samples block by block through the Planner as the servo thread would (each add
// planned at once, as firtp_tp and firtp.so add; plan_trajectory plans its adds in batches), but
// keeps no samples: only running maxima. With --generate the program
// is made on the fly, one block at a time, so memory is O(queue), not O(program):
//   spiral  an Archimedean spiral from R 60 mm, 0.5 mm apart, in chords of 0.3-0.7 mm, F6000,
//           G64 P0.05 (a long CAM-like chorded curve; at R 60 the filters' radial shrink
//           F^2 sum(T^2) / (24 R) already allows the full feed within the tolerance);
//   random  random short chords of 0.1-2 mm turning up to 90 degrees each, 100-300 mm/s,
//           0.01-0.05 mm tolerances, X Y Z;
//   corners random corners 2-40 mm apart, 100-300 mm/s, 0.05 mm (firtp_bench's BM_PlanBlock).
// Machine: the built-in one (X Y Z, 300 mm/s, 5000 mm/s^2, 10^5 mm/s^3, 1 ms, T 60/50 ms) or --ini.
//
// --per-period K adds at most K blocks between two servo ticks (firtp_tp plans one a period; by
// default as many as the queue takes). --batch adds them as plan_trajectory does (firtp plan): in
// batches planned at the next tick; each add's time is then only its queueing, and blocks/s
// counts the planning.
// Reports blocks/s (wall clock over the whole loop, sampling included), each planner.add timed on
// this thread's CPU clock and on the wall clock (mean, p50, p99, max), each period's adds and update
// together (blocks that waited beyond the window's reach join at an update), cycle time against the time
// at the programmed feeds sum(L / F) (the paper's fixed chain: the closed form sum(Tv) + sum(Td - Tk)
// + Td, as firtp plan), the largest path speed, axis velocity,
// acceleration and jerk at the samples, and peak RSS (VmHWM, bench_stats.hpp) after the first tenth of
// the blocks and at the end. Exit status 1 when the output does not rest exactly on the last
// command, or when the peak RSS grew by more than --max-growth-kib after the first tenth.
#include "bench_stats.hpp"
#include "random_corners.hpp"

#include <firtp/gcode.hpp>
#include <firtp/ini.hpp>
#include <firtp/machine.hpp>
#include <firtp/planner.hpp>
#include <firtp/trajectory.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace firtp;
using namespace firtp::bench;

namespace {

// Blocks one at a time; nothing is kept.
class Source {
public:
    virtual ~Source() = default;
    virtual std::optional<Block> next() = 0;
};

class ProgramSource : public Source {
public:
    explicit ProgramSource(Program program) : program_(std::move(program)) {}
    std::optional<Block> next() override {
        if (next_ == program_.blocks.size()) return std::nullopt;
        return program_.blocks[next_++];
    }
    const AxisVector& start() const { return program_.start; }

private:
    Program program_;
    std::size_t next_ = 0;
};

class SpiralSource : public Source {
public:
    SpiralSource(long long blocks, std::uint64_t seed) : left_(blocks), rng_(seed) {}
    std::optional<Block> next() override {
        if (left_-- <= 0) return std::nullopt;
        constexpr double r0 = 60.0, pitch = 0.5;
        const double r = r0 + pitch * theta_ / (2.0 * std::numbers::pi);
        theta_ += chord_(rng_) / r;
        const double r1 = r0 + pitch * theta_ / (2.0 * std::numbers::pi);
        Block b;
        b.target[0] = r1 * std::cos(theta_);
        b.target[1] = r1 * std::sin(theta_);
        b.feed = 100.0;
        b.tolerance = 0.05;
        b.line = ++line_;
        return b;
    }
    static AxisVector start() {
        AxisVector s = AxisVector::Zero();
        s[0] = 60.0;
        return s;
    }

private:
    long long left_;
    std::mt19937_64 rng_;
    std::uniform_real_distribution<double> chord_{0.3, 0.7};
    double theta_ = 0.0;
    std::int64_t line_ = 0;
};

// firtp_bench's BM_PlanBlock blocks (random_corners.hpp), varying feeds.
class CornerSource : public Source {
public:
    CornerSource(long long blocks, std::uint64_t seed) : left_(blocks), corners_(3, true, seed) {}
    std::optional<Block> next() override {
        if (left_-- <= 0) return std::nullopt;
        return corners_.next();
    }

private:
    long long left_;
    RandomCorners corners_;
};

class RandomChordSource : public Source {
public:
    RandomChordSource(long long blocks, std::uint64_t seed) : left_(blocks), rng_(seed) {
        direction_[0] = 1.0;
    }
    std::optional<Block> next() override {
        if (left_-- <= 0) return std::nullopt;
        // Turn by up to 90 degrees about a random axis perpendicular to the direction.
        AxisVector axis = AxisVector::Zero();
        for (int a = 0; a < 3; ++a) axis[a] = unit_(rng_);
        axis -= axis.dot(direction_) * direction_;
        if (axis.norm() > 1e-9) {
            const double angle = turn_(rng_);
            direction_ = (std::cos(angle) * direction_ + std::sin(angle) * axis.normalized()).normalized();
        }
        if (at_.norm() > 200.0 && direction_.dot(at_) > 0.0) direction_ = -direction_;  // stay near the origin
        at_ += direction_ * length_(rng_);
        Block b;
        b.target = at_;
        b.feed = feed_(rng_);
        b.tolerance = tolerance_(rng_);
        b.line = ++line_;
        return b;
    }

private:
    long long left_;
    std::mt19937_64 rng_;
    std::uniform_real_distribution<double> unit_{-1.0, 1.0}, turn_{0.0, std::numbers::pi / 2.0},
        length_{0.1, 2.0}, feed_{100.0, 300.0}, tolerance_{0.01, 0.05};
    AxisVector direction_ = AxisVector::Zero();
    AxisVector at_ = AxisVector::Zero();
    std::int64_t line_ = 0;
};

int usage(const char* self) {
    std::fprintf(stderr,
                 "usage: %s (--generate spiral|random|corners [--blocks N] [--seed S] | --program FILE.ngc) [--ini FILE] "
                 "[--json] [--max-growth-kib K] [--slowest N] [--per-period K] [--batch]\n",
                 self);
    return 2;
}

}  // namespace

int main(int argc, char** argv) try {
    std::string generate, program_file, ini_file;
    long long blocks = 1'000'000;
    std::uint64_t seed = 1;
    bool json = false;
    long max_growth_kib = -1;
    std::size_t slowest_count = 0;  // --slowest: the adds with the most CPU time, by line
    long per_period = 0;            // --per-period: at most this many adds between two ticks (0: as many as fit)
    bool batch = false;             // --batch: adds as plan_trajectory makes them (refill_due, Planning::at_update)
    for (int i = 1; i < argc; ++i) {
        const bool has_value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--json")) json = true;
        else if (!std::strcmp(argv[i], "--generate") && has_value) generate = argv[++i];
        else if (!std::strcmp(argv[i], "--program") && has_value) program_file = argv[++i];
        else if (!std::strcmp(argv[i], "--ini") && has_value) ini_file = argv[++i];
        else if (!std::strcmp(argv[i], "--blocks") && has_value) blocks = std::atoll(argv[++i]);
        else if (!std::strcmp(argv[i], "--seed") && has_value) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(argv[i], "--max-growth-kib") && has_value) max_growth_kib = std::atol(argv[++i]);
        else if (!std::strcmp(argv[i], "--slowest") && has_value) slowest_count = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--per-period") && has_value) per_period = std::atol(argv[++i]);
        else if (!std::strcmp(argv[i], "--batch")) batch = true;
        else return usage(argv[0]);
    }
    if (generate.empty() == program_file.empty()) return usage(argv[0]);

    const MachineConfig machine = ini_file.empty() ? default_machine() : load_machine(IniFile::read(ini_file));
    const PlannerParameters parameters = machine.planner_parameters();
    std::unique_ptr<Source> source;
    AxisVector start = AxisVector::Zero();
    std::string what;
    if (!program_file.empty()) {
        auto program = std::make_unique<ProgramSource>(read_gcode(program_file, machine));
        start = program->start();
        blocks = 0;
        source = std::move(program);
        what = program_file;
    } else if (generate == "spiral") {
        source = std::make_unique<SpiralSource>(blocks, seed);
        start = SpiralSource::start();
        what = "spiral";
    } else if (generate == "corners") {
        source = std::make_unique<CornerSource>(blocks, seed);
        what = "corners";
    } else if (generate == "random") {
        source = std::make_unique<RandomChordSource>(blocks, seed);
        what = "random";
    } else {
        return usage(argv[0]);
    }

    Planner planner(parameters, start);

    Histogram add_cpu(50, 5'000'000), add_wall(50, 5'000'000);  // 50 ns buckets up to 5 ms: 800 KB each
    // A servo period's planning: its adds and its update (where blocks that waited beyond the
    // window's reach join it).
    Histogram period_cpu(50, 5'000'000);
    const int axes = parameters.limits.axes;
    double max_speed = 0.0, max_v = 0.0, max_a = 0.0, max_j = 0.0;
    double tv_sum = 0.0, gaps = 0.0;
    const double td = parameters.fixed_chain ? parameters.filters.delay() : 0.0;
    long long planned = 0, corners = 0, ticks = 0;
    long warm_peak_kib = 0;
    const long long warm_after = blocks > 0 ? std::max<long long>(blocks / 10, 1) : 0;
    AxisVector last_end = start, goal = start;
    std::optional<Block> pending = source->next();
    std::vector<std::pair<std::int64_t, std::int64_t>> slowest;  // (CPU ns, line), a min-heap
    slowest.reserve(slowest_count + 1);

    const std::int64_t cpu_begin = thread_cpu_ns(), wall_begin = wall_ns();
    PlannerInput input;
    PlannerOutput output;
    const AxisState& state = output.state;
    for (Result motion = Result::working; motion == Result::working || pending;) {
        const bool room = !batch || refill_due(planner);
        std::int64_t period_ns = 0;
        for (long added = 0; room && pending && planner.free() > 0 && (per_period == 0 || added < per_period); ++added) {
            const std::int64_t c0 = thread_cpu_ns();
            const std::int64_t w0 = wall_ns();
            const Result result = planner.add(*pending, batch ? Planning::at_update : Planning::now);
            const std::int64_t w1 = wall_ns();
            const std::int64_t c1 = thread_cpu_ns();
            if (result == Result::queue_full) break;
            if (refused(result)) {
                std::fprintf(stderr, "line %lld: %s\n", static_cast<long long>(pending->line), planner.refusal());
                return 1;
            }
            add_cpu.add(c1 - c0);
            add_wall.add(w1 - w0);
            period_ns += c1 - c0;
            slowest.emplace_back(c1 - c0, pending->line);  // the N slowest on the CPU clock
            std::push_heap(slowest.begin(), slowest.end(), std::greater<>());
            if (slowest.size() > slowest_count) {
                std::pop_heap(slowest.begin(), slowest.end(), std::greater<>());
                slowest.pop_back();
            }
            if (result == Result::ok) {  // not skipped (zero length)
                tv_sum += (pending->target - last_end).norm() / pending->feed;
                last_end = pending->target;
            }
            goal = pending->target;
            if (++planned == warm_after) warm_peak_kib = peak_rss_kib();
            pending = source->next();
        }
        input.end_of_program = !pending;
        const std::int64_t u0 = thread_cpu_ns();
        motion = planner.update(input, output);
        period_cpu.add(period_ns + thread_cpu_ns() - u0);
        for (CornerReport corner; planner.take_report(corner);) {
            ++corners;
            gaps += td - corner.Tk;
        }
        ++ticks;
        max_speed = std::max(max_speed, state.velocity.norm());
        for (int a = 0; a < axes; ++a) {
            max_v = std::max(max_v, std::abs(state.velocity[a]));
            max_a = std::max(max_a, std::abs(state.acceleration[a]));
            max_j = std::max(max_j, std::abs(state.jerk[a]));
        }
    }
    const double cpu_s = static_cast<double>(thread_cpu_ns() - cpu_begin) * 1e-9;
    const double wall_s = static_cast<double>(wall_ns() - wall_begin) * 1e-9;
    const bool exact = state.position == goal && state.velocity == AxisVector::Zero();
    const long end_peak_kib = peak_rss_kib();
    if (warm_peak_kib == 0) warm_peak_kib = end_peak_kib;
    const double cycle_time = state.time;
    const double closed_form = parameters.fixed_chain ? tv_sum + gaps + td : tv_sum;
    // What plan_trajectory would have held: every sample.
    const double samples_mib = static_cast<double>(ticks) * static_cast<double>(sizeof(AxisState)) / (1024.0 * 1024.0);
    const bool flat = max_growth_kib < 0 || end_peak_kib - warm_peak_kib <= max_growth_kib;

    if (json) {
        std::printf("{\"source\":\"%s\",\"blocks\":%lld,\"corners\":%lld,\"ticks\":%lld,\"wall_s\":%.3f,\"cpu_s\":%.3f,"
                    "\"blocks_per_s\":%.0f,\"blocks_per_cpu_s\":%.0f,\"add_cpu_ns\":%s,\"add_wall_ns\":%s,\"period_cpu_ns\":%s,"
                    "\"cycle_time_s\":%.6f,\"closed_form_cycle_time_s\":%.6f,"
                    "\"max_speed\":%.3f,\"max_axis_velocity\":%.3f,\"max_axis_acceleration\":%.3f,\"max_axis_jerk\":%.3f,"
                    "\"peak_rss_kib_after_first_tenth\":%ld,\"peak_rss_kib\":%ld,\"samples_mib_if_kept\":%.1f,"
                    "\"end_exact\":%s,\"flat\":%s}\n",
                    what.c_str(), planned, corners, ticks, wall_s, cpu_s, static_cast<double>(planned) / wall_s,
                    static_cast<double>(planned) / cpu_s, add_cpu.json().c_str(), add_wall.json().c_str(), period_cpu.json().c_str(), cycle_time,
                    closed_form, max_speed, max_v, max_a, max_j, warm_peak_kib, end_peak_kib,
                    samples_mib, exact ? "true" : "false", flat ? "true" : "false");
    } else {
        std::printf("%s: %lld blocks, %lld corners, %lld servo periods planned and sampled in %.2f s (%.2f s CPU)\n",
                    what.c_str(), planned, corners, ticks, wall_s, cpu_s);
        std::printf("  %.0f blocks/s (wall), %.0f blocks per CPU second\n", static_cast<double>(planned) / wall_s,
                    static_cast<double>(planned) / cpu_s);
        std::printf("  planner.add, thread CPU clock: mean %.1f us, p50 %.1f, p99 %.1f, max %.1f us\n",
                    add_cpu.mean() * 1e-3, static_cast<double>(add_cpu.quantile(0.5)) * 1e-3,
                    static_cast<double>(add_cpu.quantile(0.99)) * 1e-3, static_cast<double>(add_cpu.max()) * 1e-3);
        std::printf("  planner.add, wall clock:       mean %.1f us, p50 %.1f, p99 %.1f, max %.1f us (maxima include preemption)\n",
                    add_wall.mean() * 1e-3, static_cast<double>(add_wall.quantile(0.5)) * 1e-3,
                    static_cast<double>(add_wall.quantile(0.99)) * 1e-3, static_cast<double>(add_wall.max()) * 1e-3);
        std::printf("  a period (its adds and update), thread CPU clock: mean %.1f us, p50 %.1f, p99 %.1f, max %.1f us\n",
                    period_cpu.mean() * 1e-3, static_cast<double>(period_cpu.quantile(0.5)) * 1e-3,
                    static_cast<double>(period_cpu.quantile(0.99)) * 1e-3, static_cast<double>(period_cpu.max()) * 1e-3);
        std::sort(slowest.begin(), slowest.end(), std::greater<>());
        for (const auto& [ns, line] : slowest) std::printf("  slow add: line %lld, %.1f us CPU\n", static_cast<long long>(line), static_cast<double>(ns) * 1e-3);
        std::printf("  cycle time %.4f s (%s %.4f s)\n", cycle_time, parameters.fixed_chain ? "closed form" : "at the feeds",
                    closed_form);
        std::printf("  max path speed %.1f, axis v %.1f, a %.0f, j %.0f\n", max_speed, max_v, max_a, max_j);
        std::printf("  peak RSS %ld KiB after the first tenth, %ld KiB at the end (keeping the samples: %.0f MiB more)\n",
                    warm_peak_kib, end_peak_kib, samples_mib);
        std::printf("  end: %s\n", exact ? "exactly on the last command" : "NOT on the last command");
    }
    if (!flat) std::fprintf(stderr, "peak RSS grew by %ld KiB after the first tenth\n", end_peak_kib - warm_peak_kib);
    return exact && flat ? 0 : 1;
} catch (const std::exception& e) {
    std::fprintf(stderr, "firtp_plan_stream: %s\n", e.what());
    return 1;
}
