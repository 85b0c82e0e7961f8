// Real-time proof: the servo-thread calls make no heap allocation and take no lock, over long
// random programs with overrides, holds, aborts, disabling and stream faults. Counted by hooks in
// this program (rt_probe.hpp), armed around the servo-thread calls only:
//   ComponentLogic::update (the component's real-time logic, planning on acceptance included),
//   Planner::add and update, TpCore's servo-thread calls (firtp_tp's tpRunCycle, tpAdd*, tpPause ...),
//   and firtp.update itself in firtp.so, run by hal-shim's servo thread (stepped, and on the
//   real-time clock while the host and the bridge stream over LCM in another thread).
#include "random_operation.hpp"
#include "rt_probe.hpp"

#include <firtp/host.hpp>
#include <firtp/messages.hpp>
#include <firtp/planner.hpp>
#include <firtp/in_process_component.hpp>
#include <firtp/hal_shim/runtime.hpp>
#include <hal.h>
#include <tp_core.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

using namespace firtp;

namespace {

// Keeps a pointer alive so the compiler cannot drop an allocation.
void escape(void* p) { asm volatile("" : : "g"(p) : "memory"); }

struct Totals {
    long calls = 0, allocations = 0, frees = 0, locks = 0;
    void add(const rt_probe::Counts& c) {
        ++calls;
        allocations += c.allocations;
        frees += c.frees;
        locks += c.locks;
    }
};

void expect_clean(const Totals& t, const char* what) {
    EXPECT_EQ(t.allocations, 0) << what;
    EXPECT_EQ(t.frees, 0) << what;
    if (rt_probe::locks_counted()) {
        EXPECT_EQ(t.locks, 0) << what;
    }
    std::printf("%s: %ld calls, %ld allocations, %ld frees, %s locks\n", what, t.calls, t.allocations, t.frees,
                rt_probe::locks_counted() ? std::to_string(t.locks).c_str() : "(not counted under TSan)");
}

}  // namespace

// The probe sees what it must: allocations (malloc and new), frees and locks of this thread only.
TEST(RtProbe, CountsAllocationsFreesAndLocksOfTheArmedThreadOnly) {
    std::mutex m;
    rt_probe::arm();
    void* p = std::malloc(24);
    escape(p);
    std::free(p);
    auto* v = new std::vector<int>(100);  // two allocations: the vector and its storage
    escape(v);
    delete v;
    m.lock();
    m.unlock();
    std::thread([] {  // another thread's allocations are not counted
        for (int i = 0; i < 10; ++i) {
            int* q = new int(i);
            escape(q);
            delete q;
        }
    }).join();
    const rt_probe::Counts c = rt_probe::disarm();
    // pthread_create and join allocate and lock in this thread; the probe counts them too.
    EXPECT_GE(c.allocations, 3);
    EXPECT_GE(c.frees, 3);
    EXPECT_LT(c.allocations, 10) << "another thread's allocations were counted";
    if (rt_probe::locks_counted()) {
        EXPECT_GE(c.locks, 1);
    }

    rt_probe::arm();
    int* one_int = new int(1);
    escape(one_int);
    const rt_probe::Counts one = rt_probe::current();
    rt_probe::disarm();
    delete one_int;
    EXPECT_EQ(one.allocations, 1);
    rt_probe::arm();
    const rt_probe::Counts none = rt_probe::disarm();
    EXPECT_EQ(none.allocations, 0);
    EXPECT_EQ(none.locks, 0);
}

// ComponentLogic::update over 30 simulated minutes of random programs on two machines: with axis
// limits (planned on the samples) and without (closed-form overlaps).
class ComponentRealTime : public ::testing::TestWithParam<bool> {};

TEST_P(ComponentRealTime, UpdateNeitherAllocatesNorLocks) {
    const bool limits = GetParam();
    const ComponentSettings settings = test::operation_settings(limits);
    ComponentLogic core(settings);
    test::StreamRing ring;
    test::OperationOptions options;
    options.max_program_blocks = 120;
    options.gap_chance = options.nan_chance = 0.002;
    options.repeat_chance = 0.01;
    options.disables_per_s = 0.01;  // about 9 in the run: the count below holds whatever the motion's timing
    test::RandomOperation op(settings, limits ? 101 : 202, options);
    ComponentOutputs out;
    Totals totals;
    const std::int64_t ticks = 900'000;  // 15 minutes at 1 kHz
    for (std::int64_t k = 0; k < ticks; ++k) {
        op.before_tick(ring);
        rt_probe::arm();
        core.update(op.inputs(), ring.source(), out);
        totals.add(rt_probe::disarm());
        op.after_tick(out, ring);
        if (!op.ok()) break;
    }
    const test::OperationStats& s = op.stats();
    EXPECT_TRUE(op.ok()) << s.first_violation;
    expect_clean(totals, limits ? "ComponentLogic::update, machine with limits" : "ComponentLogic::update, no limits");
    std::printf("  %lld ticks, %lld blocks, %lld programs: %lld completed, %lld aborted, %lld disabled (%lld braked), %lld faults "
                "(gap, NaN), %lld repeats refused; %lld overrides, %lld holds; end error %.3g mm; |v|,|a|/limit %.6f\n",
                static_cast<long long>(s.ticks), static_cast<long long>(s.blocks), static_cast<long long>(s.programs),
                static_cast<long long>(s.completed), static_cast<long long>(s.aborted),
                static_cast<long long>(s.disabled), static_cast<long long>(s.braked), static_cast<long long>(s.faulted),
                static_cast<long long>(s.repeats), static_cast<long long>(s.overrides),
                static_cast<long long>(s.holds), s.worst_end_error, s.worst_limit_ratio);
    EXPECT_EQ(totals.calls, ticks);
    EXPECT_GT(s.blocks, 3000);
    EXPECT_GT(s.completed, 20);
    EXPECT_GT(s.aborted, 5);
    EXPECT_GT(s.disabled, 2);
    EXPECT_GT(s.braked, 0);
    EXPECT_GT(s.faulted, 2);
    EXPECT_GT(s.repeats, 20);
    EXPECT_GT(s.holds, 30);
    EXPECT_LE(s.worst_end_error, 1e-9);
    EXPECT_LE(s.worst_limit_ratio, 1.0 + 1e-6);
}

std::string machine_name(const ::testing::TestParamInfo<bool>& p) { return p.param ? "WithLimits" : "NoLimits"; }
INSTANTIATE_TEST_SUITE_P(Machines, ComponentRealTime, ::testing::Values(true, false), machine_name);

// The planner alone, adding blocks and ticking in the counted calls (both run in the servo
// thread): bursts of blocks, rate changes, holds and aborts (stop, then everything dropped), at
// the limits and with the paper's fixed chain.
class PlannerRealTime : public ::testing::TestWithParam<bool> {};

TEST_P(PlannerRealTime, AddAndUpdateNeitherAllocateNorLock) {
    static_assert(noexcept(std::declval<Planner&>().update(PlannerInput{}, std::declval<PlannerOutput&>())));
    PlannerParameters p = test::operation_settings(GetParam()).planner;
    p.queue_capacity = 64;
    Planner planner(p, AxisVector::Zero());
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Totals totals;
    PlannerInput input;
    PlannerOutput output;
    AxisVector target = AxisVector::Zero();
    int aborts = 0, bursts = 0, ends = 0;
    bool aborting = false;
    Result motion = Result::finished;
    for (int k = 0; k < 600'000; ++k) {
        rt_probe::arm();
        if (!aborting && motion == Result::finished) {  // at rest: exactly on the last target; the next burst
            ASSERT_EQ(output.state.position, target);
            ends += bursts > 0;
            ++bursts;
            const int n = 1 + static_cast<int>(unit(rng) * 40);
            // A third of the bursts zig-zag (2 mm legs turning by 174 degrees): corners overlapped by Tk.
            const bool zig_zag = unit(rng) < 0.3;
            for (int i = 0; i < n && planner.free() > 0; ++i) {
                Block b;
                if (zig_zag) {
                    b.target = target;
                    b.target[0] += i % 2 == 0 ? 2.0 : -2.0;
                    b.target[1] += 0.105;
                } else {
                    for (int a = 0; a < 3; ++a) b.target[a] = target[a] + 20.0 * (unit(rng) - 0.5);
                }
                b.feed = zig_zag ? 20 + 30 * unit(rng) : 10 + 290 * unit(rng);
                b.tolerance = zig_zag ? 0.3 + 0.2 * unit(rng) : 0.01 + 0.2 * unit(rng);
                ASSERT_EQ(planner.add(b), Result::ok);
                target = b.target;
            }
            input.end_of_program = true;
        }
        const double u = unit(rng);
        if (!aborting && u < 0.001) {
            input.hold = u < 0.0002;
            input.rate = 0.3 + 1.2 * unit(rng);
        }
        if (!aborting && u > 0.9998 && !planner.idle()) planner.abort(), aborting = true, ++aborts;
        motion = planner.update(input, output);
        totals.add(rt_probe::disarm());
        if (output.flushed) {  // stopped on the path, everything dropped: plan from there
            target = planner.rest_position();
            input = PlannerInput{};
            aborting = false;
        }
    }
    expect_clean(totals, "Planner::add and Planner::update");
    std::printf("  %d bursts of blocks ended exactly on their target, %d aborts, %llu corners overlapped\n", ends, aborts,
                static_cast<unsigned long long>(planner.stats().overlapped));
    EXPECT_GT(aborts, 10);
    EXPECT_GT(ends, 100);
    if (GetParam()) {  // at the limits: turns overlapped by Tk, counted too
        EXPECT_GT(planner.stats().overlapped, 100u);
    }
}
INSTANTIATE_TEST_SUITE_P(Machines, PlannerRealTime, ::testing::Values(true, false), machine_name);

// A dense path fed a block a period, as firtp_tp feeds it, into a deep window: blocks added beyond
// the window's reach wait and join it in batches at an update (lookahead_reach.cpp), whose undo
// copies the window into storage made at construction. Overrides and holds among them.
TEST(PlannerRealTime, BlocksJoiningInBatchesNeitherAllocateNorLock) {
    PlannerParameters p = test::operation_settings(true).planner;
    p.queue_capacity = 1024;
    Planner planner(p, AxisVector::Zero());
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Totals totals;
    PlannerInput input;
    PlannerOutput output;
    Block b;
    b.feed = 300.0;
    b.tolerance = 0.5;
    int added = 0;
    for (int k = 0; k < 200'000; ++k) {
        rt_probe::arm();
        if (added < 60'000 && planner.free() > 0) {  // a helix of R20 in 0.35 mm chords
            ++added;
            const double angle = 2.0 * std::numbers::pi * added / 360.0;
            b.target[0] = 20.0 * std::cos(angle) - 20.0;
            b.target[1] = 20.0 * std::sin(angle);
            b.target[2] = 0.05 * added / 360.0;
            b.line = added;
            ASSERT_EQ(planner.add(b), Result::ok);
        }
        input.end_of_program = added == 60'000;
        const double u = unit(rng);
        if (u < 0.0005) input.hold = u < 0.0001, input.rate = 0.3 + 1.2 * unit(rng);
        planner.update(input, output);
        totals.add(rt_probe::disarm());
    }
    expect_clean(totals, "Planner::add and Planner::update, blocks joining in batches");
    std::printf("  %d chords added, %llu joined after waiting beyond the window, in %llu later steps\n", added,
                static_cast<unsigned long long>(planner.stats().rejoined),
                static_cast<unsigned long long>(planner.stats().join_steps));
    EXPECT_GT(planner.stats().rejoined, 10'000u);
    EXPECT_GT(planner.stats().join_steps, 1'000u);  // joins spread over periods ran here too
}

// firtp_tp's servo-thread calls: a move added per period when there is room (lines and arcs),
// run_cycle every period, pause/resume, override and aborts; the rebuild for the axis limits
// happens before counting starts (it allocates by design, from the module's arena).
TEST(TpCoreRealTime, ServoThreadCallsNeitherAllocateNorLock) {
    using namespace firtp::linuxcnc_tp;
    TpSettings s;
    s.jerk = 1e5;
    s.default_tolerance = 0.05;
    s.plan_budget_ns = 0;  // no time budget: the same work in every build (sanitizers are slower)
    TpCore tp(s);
    Pose vmax{}, amax{};
    for (int a = 0; a < 3; ++a) vmax[a] = 300, amax[a] = 5000;
    tp.set_axis_limits(vmax, amax);
    tp.set_position(Pose{});
    CycleInputs in;
    in.max_feed_scale = 1.0;
    tp.run_cycle(in);  // rebuilds the planner with the limits (allocates)

    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Totals totals;
    Pose goal{};
    int moves_left = 0, id = 0, programs = 0, completed = 0, aborts = 0, arcs = 0;
    bool aborting = false, paused = false;
    double worst_end = 0.0;
    for (int k = 0; k < 400'000; ++k) {
        if (moves_left == 0 && !aborting && tp.done() && !paused) {
            // A finished program ends exactly where it was sent.
            if (programs > 0) {
                for (int a = 0; a < 3; ++a) worst_end = std::max(worst_end, std::abs(tp.position()[a] - goal[a]));
                ++completed;
            }
            moves_left = 1 + static_cast<int>(unit(rng) * 60);
            ++programs;
        }
        const double u = unit(rng);
        rt_probe::arm();
        if (moves_left > 0 && !aborting && !tp.full()) {
            MoveRequest m;
            m.vel = 10 + 290 * unit(rng);
            m.acc = 5000;
            m.motion_type = motion_feed;
            tp.set_id(++id);
            tp.set_term_cond(unit(rng) < 0.05 ? term_stop : term_parabolic, 0.005 + 0.1 * unit(rng));
            if (unit(rng) < 0.1) {  // an arc in X Y from the goal, counter-clockwise
                const double r = 1 + 10 * unit(rng), phi = 2 * std::numbers::pi * unit(rng), sweep = 0.2 + 2.5 * unit(rng);
                const Vec3 center{goal[0] - r * std::cos(phi), goal[1] - r * std::sin(phi), goal[2]};
                m.end = goal;
                m.end[0] = center[0] + r * std::cos(phi + sweep);
                m.end[1] = center[1] + r * std::sin(phi + sweep);
                m.motion_type = motion_arc;
                if (tp.add_arc(m, {center, {0, 0, 1}, 0}) == AddStatus::ok) goal = m.end, ++arcs;
            } else {
                m.end = goal;
                for (int a = 0; a < 3; ++a) m.end[a] = std::clamp(goal[a] + 30 * (unit(rng) - 0.5), -200.0, 200.0);
                if (tp.add_line(m) == AddStatus::ok) goal = m.end;
            }
            --moves_left;
        }
        if (u < 0.0005) in.feed_scale = unit(rng);
        else if (u < 0.001) in.feed_scale = 1.0;
        else if (u < 0.0012 && !paused) tp.pause(), paused = true;
        else if (u < 0.003 && paused) tp.resume(), paused = false;
        else if (u > 0.99997 && !aborting && !tp.done()) tp.abort(), aborting = true, ++aborts;
        tp.run_cycle(in);
        (void)tp.exec_id();
        (void)tp.exec_tag();
        (void)tp.distance_to_go();
        (void)tp.current_vel();
        const bool done = tp.done();
        totals.add(rt_probe::disarm());
        if (aborting && done) {  // stopped on the path, everything dropped: start again from there
            aborting = false;
            moves_left = 0;
            paused = false;
            tp.resume();
            goal = tp.position();
            programs = 0;  // the next finished program is checked, not this one
        }
    }
    expect_clean(totals, "TpCore servo-thread calls (tpAdd*, tpRunCycle, tpPause/Resume/Abort, status)");
    std::printf("  %d ids, %d arcs, %d completed programs, %d aborts, end error %.3g mm\n", id, arcs, completed, aborts,
                worst_end);
    EXPECT_GT(completed, 10);
    EXPECT_GT(aborts, 3);
    EXPECT_GT(arcs, 50);
    EXPECT_LE(worst_end, 1e-9);
}

// ---- firtp.update in firtp.so under hal-shim -----------------------------------------------------

namespace {

namespace shim = firtp::hal_shim;

// A HAL component whose two functions bracket firtp.update in the servo thread's list.
std::atomic<long> probe_calls{0}, probe_allocations{0}, probe_frees{0}, probe_locks{0};

void probe_arm(void*, long) { rt_probe::arm(); }
void probe_disarm(void*, long) {
    const rt_probe::Counts c = rt_probe::disarm();
    probe_calls.fetch_add(1);
    probe_allocations.fetch_add(c.allocations);
    probe_frees.fetch_add(c.frees);
    probe_locks.fetch_add(c.locks);
}

struct Probe {
    int comp = -1;
    Probe() {
        probe_calls = probe_allocations = probe_frees = probe_locks = 0;
        comp = hal_init("rtprobe");
        EXPECT_GT(comp, 0);
        EXPECT_EQ(hal_export_funct("rtprobe.arm", probe_arm, nullptr, 1, 0, comp), 0);
        EXPECT_EQ(hal_export_funct("rtprobe.disarm", probe_disarm, nullptr, 1, 0, comp), 0);
        EXPECT_EQ(hal_ready(comp), 0);
        EXPECT_TRUE(shim::add_funct("rtprobe.arm", "servo-thread", 1).ok());
        EXPECT_TRUE(shim::add_funct("rtprobe.disarm", "servo-thread", -1).ok());
    }
    ~Probe() {
        shim::del_funct("rtprobe.arm", "servo-thread");
        shim::del_funct("rtprobe.disarm", "servo-thread");
        hal_exit(comp);
    }
    Totals totals() const { return {probe_calls.load(), probe_allocations.load(), probe_frees.load(), probe_locks.load()}; }
    Probe(const Probe&) = delete;
    Probe& operator=(const Probe&) = delete;
};

Program random_program(std::uint64_t seed, int blocks, const AxisVector& start) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Program p;
    p.file = "random.ngc";
    p.start = start;
    AxisVector at = start;
    for (int i = 0; i < blocks; ++i) {
        Block b;
        for (int a = 0; a < 3; ++a) b.target[a] = at[a] + (unit(rng) < 0.3 ? 0.3 : 15.0) * (unit(rng) - 0.5);
        b.feed = 20 + 230 * unit(rng);
        b.tolerance = 0.01 + 0.1 * unit(rng);
        b.termination = unit(rng) < 0.05 ? Termination::exact_stop : Termination::blend;
        b.line = i + 1;
        p.blocks.push_back(b);
        at = b.target;
    }
    return p;
}

}  // namespace

// Stepped: one servo period at a time in this thread; the host streams over memq:// with a clock
// that advances one period per step. Overrides, holds, an abort of the first program, then a
// second program to its end.
TEST(FirtpModuleRealTime, UpdateUnderHalShimNeitherAllocatesNorLocks) {
    auto lcm = messages::open("memq://");
    const MachineConfig machine = default_machine();
    InProcessComponent chain(*lcm, machine, default_module_path());
    Probe probe;
    std::int64_t periods = 0;
    host::HostOptions options;
    options.clock = [&] { return host::Clock::time_point(std::chrono::milliseconds(periods)); };
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> unit(0.0, 1.0);

    auto run = [&](host::Host& h, int abort_at) {
        for (int k = 0; k < 2'000'000 && h.result() == host::Result::running; ++k) {
            h.step();
            while (lcm->handleTimeout(0) > 0) {
            }
            chain.step();
            chain.poll();
            ++periods;
            const double u = unit(rng);
            if (u < 0.001) h.set_feed_scale(1.5 * unit(rng));
            else if (u < 0.0015) h.hold(true);
            else if (u < 0.004) h.hold(false);
            if (k == abort_at) h.abort();
        }
        return h.result();
    };
    const Program first = random_program(1, 400, AxisVector::Zero());
    options.program_id = 1;
    host::Host a(*lcm, first, options);
    EXPECT_EQ(run(a, 6000), host::Result::aborted) << a.error();
    options.program_id = 2;
    options.record_axis_states = true;
    // The second program starts where the first stopped: its blocks are absolute.
    const Program second = random_program(2, 300, AxisVector::Zero());
    host::Host b(*lcm, second, options);
    EXPECT_EQ(run(b, -1), host::Result::done) << b.error();
    ASSERT_FALSE(b.axis_states().empty());
    const auto& last = b.axis_states().back();
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(last.position[i], second.blocks.back().target[i], 1e-9);
    const Totals t = probe.totals();
    expect_clean(t, "firtp.update in firtp.so (hal-shim, stepped)");
    EXPECT_EQ(t.calls, periods);
    EXPECT_GT(periods, 20000);
    std::printf("  %lld periods, %lld + %lld blocks published, %lld go-backs\n", static_cast<long long>(periods),
                static_cast<long long>(a.statistics().blocks_published),
                static_cast<long long>(b.statistics().blocks_published),
                static_cast<long long>(a.statistics().go_backs + b.statistics().go_backs));
}

// On the real-time clock: hal-shim's servo thread runs firtp.update every millisecond while this
// thread runs the host and the bridge (LCM, the block stream's writer side). Only the servo
// thread is counted.
TEST(FirtpModuleRealTime, UpdateOnTheServoThreadNeitherAllocatesNorLocksWhileTheHostStreams) {
    auto lcm = messages::open("memq://");
    const MachineConfig machine = default_machine();
    InProcessComponent chain(*lcm, machine, default_module_path());
    Probe probe;
    const Program program = random_program(3, 15, AxisVector::Zero());
    host::HostOptions options;
    options.program_id = 1;
    options.record_axis_states = true;
    host::Host h(*lcm, program, options);
    chain.start();
    const auto begin = std::chrono::steady_clock::now();
    bool held = false;
    while (h.result() == host::Result::running && std::chrono::steady_clock::now() - begin < std::chrono::seconds(60)) {
        h.step();
        while (lcm->handleTimeout(0) > 0) {
        }
        chain.poll();
        const auto elapsed = std::chrono::steady_clock::now() - begin;
        if (!held && elapsed > std::chrono::milliseconds(300)) h.hold(true), h.set_feed_scale(0.7), held = true;
        if (held && elapsed > std::chrono::milliseconds(1300)) h.hold(false);
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    EXPECT_EQ(h.result(), host::Result::done) << h.error();
    const Totals t = probe.totals();
    expect_clean(t, "firtp.update in firtp.so (hal-shim servo thread at 1 kHz, host and bridge streaming)");
    EXPECT_GT(t.calls, 1000);
    ASSERT_FALSE(h.axis_states().empty());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(h.axis_states().back().position[i], program.blocks.back().target[i], 1e-9);
}
