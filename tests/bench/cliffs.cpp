// Cliffs: does a better machine ever make a program slower? Random machines and programs
// (tests/core/support/random_machine.hpp), each planned again with one limit raised by a quarter
// (an axis' velocity, acceleration or jerk) or every tolerance raised by a quarter; the cycle time
// of the samples is compared. Issue 13 asks for none slower; this measures how far from that the
// planner is (docs/BENCHMARKS.md):
//
//     firtp_cliffs [--programs N] [--seed S] [--list] [--times] [--check]
//
// --list prints each slower case: program index, what was raised, blocks, both cycle times.
// --times prints every plan's cycle time (program, what was raised): two planners side by side.
// --check measures every plan on its samples (support/case_ratios.hpp): each one outside its
// limits or tolerances is printed, and the worst ratios at the end.
#include "support/case_ratios.hpp"
#include "support/random_machine.hpp"

#include <firtp/trajectory.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace firtp;

namespace {
// --dump K: program K's machine, blocks and corner reports, before and after each raise.
void dump_case(const PlannerParameters& p, const std::vector<Block>& blocks, const char* title) {
    std::fprintf(stderr, "=== %s\n", title);
    const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
    std::printf("  %s: cycle %.6f s, period %g, max_rate %g, slowed %llu checks_failed %llu unfit %llu\n", title, t.cycle_time, p.period, p.max_rate, (unsigned long long)t.stats.slowed, (unsigned long long)t.stats.checks_failed, (unsigned long long)t.stats.unfit);
    for (int a = 0; a < p.limits.axes; ++a)
        std::printf("    axis %d: v %g a %g j %g\n", a, p.limits.axis[a].max_velocity, p.limits.axis[a].max_acceleration,
                    p.limits.axis[a].max_jerk);
    AxisVector at = AxisVector::Zero();
    for (const Block& b : blocks) {
        std::printf("    line %lld: length %.4f feed %g tol %g%s%s\n", static_cast<long long>(b.line), (b.target - at).norm(), b.feed,
                    b.tolerance, b.termination == Termination::exact_stop ? " G61" : "", b.type == MotionType::traverse ? " G0" : "");
        at = b.target;
        std::printf("      to");
        for (int a = 0; a < p.limits.axes; ++a) std::printf(" %.17g", b.target[a]);
        std::printf("\n");
    }
    std::int64_t line = -1;
    double since = 0.0, top = 0.0;
    for (const AxisState& x : t.samples) {
        if (x.line != line) {
            if (line >= 0) std::printf("    samples line %lld: %.3f s, top speed %.3f\n", static_cast<long long>(line), x.time - since, top);
            line = x.line, since = x.time, top = 0.0;
        }
        top = std::max(top, x.velocity.norm());
    }
    std::printf("    samples line %lld: %.3f s, top speed %.3f\n", static_cast<long long>(line), t.cycle_time - since, top);
    for (const CornerReport& r : t.corners)
        std::printf("    corner %lld: beta %.1f deg, %.3f -> %.3f, %s, err %.4g / %.4g\n", static_cast<long long>(r.line),
                    r.beta * 180.0 / 3.141592653589793, r.speed_in, r.speed_out, describe(r.bound), r.predicted_error, r.epsilon);
}
}  // namespace

int main(int argc, char** argv) {
    int programs = 150;
    std::uint64_t seed = 31;
    bool list = false, times = false, check = false;
    int dump = -1;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--list") == 0) list = true;
        else if (std::strcmp(argv[i], "--times") == 0) times = true;
        else if (std::strcmp(argv[i], "--check") == 0) check = true;
        else if (i + 1 < argc && std::strcmp(argv[i], "--programs") == 0) programs = std::atoi(argv[++i]);
        else if (i + 1 < argc && std::strcmp(argv[i], "--seed") == 0) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (i + 1 < argc && std::strcmp(argv[i], "--dump") == 0) dump = std::atoi(argv[++i]);
        else {
            std::fprintf(stderr, "usage: firtp_cliffs [--programs N] [--seed S] [--list] [--times] [--check] [--dump K]\n");
            return 2;
        }
    }
    const char* names[] = {"velocity", "acceleration", "jerk", "tolerance"};
    std::array<int, 4> tried{}, slower{};
    std::array<double, 4> worst{};
    double total = 0.0, log_total = 0.0;  // over every plan: to compare two planners on the same programs
    int plans = 0;
    std::mt19937_64 rng(seed);
    test::CaseRatios worst_measured;
    int measured = 0, outside = 0;
    int k = 0;
    const char* what = "base";
    auto cycle = [&](const PlannerParameters& p, const std::vector<Block>& blocks) {
        const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
        if (check) {
            const test::CaseRatios r = test::case_ratios(p, blocks, t);
            ++measured;
            if (!r.within())
                ++outside, std::printf("program %d %s outside: corner %.6f v %.9f a %.9f j %.9f end %d rest %d\n", k, what, r.corner,
                                       r.velocity, r.acceleration, r.jerk, r.end_exact, r.at_rest);
            worst_measured.take_worst(r);
        }
        return t.cycle_time;
    };
    for (; k < programs; ++k) {
        what = "base";
        const test::CliffsProgram drawn = test::cliffs_program(rng);
        const test::RandomCase& c = drawn.c;
        const double base = cycle(c.parameters, c.blocks);
        if (base > 0.0) total += base, log_total += std::log(base), ++plans;
        if (times) std::printf("program %d base %.6f\n", k, base);
        for (int variant = 0; variant < 4; ++variant) {
            PlannerParameters p = c.parameters;
            std::vector<Block> blocks = c.blocks;
            if (variant < 3) {
                AxisLimits& l = p.limits.axis[drawn.raised_axis[static_cast<std::size_t>(variant)]];
                double& limit = variant == 0 ? l.max_velocity : variant == 1 ? l.max_acceleration : l.max_jerk;
                if (!(limit > 0.0)) continue;
                limit *= 1.25;
            } else {
                for (Block& b : blocks) b.tolerance *= 1.25;
            }
            what = names[variant];
            const double raised = cycle(p, blocks);
            if (raised > 0.0) total += raised, log_total += std::log(raised), ++plans;
            if (times) std::printf("program %d %s %.6f\n", k, names[variant], raised);
            if (k == dump) {
                std::printf("program %d, %s raised\n", k, names[variant]);
                dump_case(c.parameters, c.blocks, "before");
                dump_case(p, blocks, "after");
            }
            ++tried[static_cast<std::size_t>(variant)];
            if (raised > base + 1e-12) {
                if (list)
                    std::printf("program %d: %s raised: %zu blocks, %.6f s -> %.6f s (%+.1f %%)\n", k, names[variant],
                                blocks.size(), base, raised, 100.0 * (raised / base - 1.0));
                ++slower[static_cast<std::size_t>(variant)];
                worst[static_cast<std::size_t>(variant)] = std::max(worst[static_cast<std::size_t>(variant)], raised / base - 1.0);
            }
        }
    }
    std::printf("%d plans: cycle times sum %.6f s, geometric mean %.6f s\n", plans, total, std::exp(log_total / plans));
    if (check)
        std::printf("%d plans measured, %d outside: worst corner error %.6f of the tolerance, v %.9f a %.9f j %.9f of the limits\n",
                    measured, outside, worst_measured.corner, worst_measured.velocity, worst_measured.acceleration, worst_measured.jerk);
    std::printf("| raised by 25 %% | programs | slower | worst slow-down |\n|---|---:|---:|---:|\n");
    for (std::size_t v = 0; v < 4; ++v)
        std::printf("| %s | %d | %d | %.1f %% |\n", names[v], tried[v], slower[v], 100.0 * worst[v]);
    return 0;
}
