// Cliffs: does a better machine ever make a program slower? Random machines and programs
// (tests/core/support/random_machine.hpp), each planned again with one limit raised by a quarter
// (an axis' velocity, acceleration or jerk) or every tolerance raised by a quarter; the cycle time
// of the samples is compared. Issue 13 asks for none slower; this measures how far from that the
// planner is (docs/BENCHMARKS.md):
//
//     firtp_cliffs [--programs N] [--seed S] [--list]
//
// --list prints each slower case: program index, what was raised, blocks, both cycle times.
#include "support/random_machine.hpp"

#include <firtp/trajectory.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace firtp;

int main(int argc, char** argv) {
    int programs = 150;
    std::uint64_t seed = 31;
    bool list = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--list") == 0) list = true;
        else if (i + 1 < argc && std::strcmp(argv[i], "--programs") == 0) programs = std::atoi(argv[++i]);
        else if (i + 1 < argc && std::strcmp(argv[i], "--seed") == 0) seed = std::strtoull(argv[++i], nullptr, 10);
        else {
            std::fprintf(stderr, "usage: firtp_cliffs [--programs N] [--seed S] [--list]\n");
            return 2;
        }
    }
    const char* names[] = {"velocity", "acceleration", "jerk", "tolerance"};
    std::array<int, 4> tried{}, slower{};
    std::array<double, 4> worst{};
    std::mt19937_64 rng(seed);
    auto cycle = [](const PlannerParameters& p, const std::vector<Block>& blocks) {
        return plan_trajectory(p, AxisVector::Zero(), blocks).cycle_time;
    };
    for (int k = 0; k < programs; ++k) {
        const test::RandomCase c = test::random_case(rng);
        const double base = cycle(c.parameters, c.blocks);
        for (int variant = 0; variant < 4; ++variant) {
            PlannerParameters p = c.parameters;
            std::vector<Block> blocks = c.blocks;
            if (variant < 3) {
                AxisLimits& l = p.limits.axis[rng() % static_cast<unsigned>(p.limits.axes)];
                double& limit = variant == 0 ? l.max_velocity : variant == 1 ? l.max_acceleration : l.max_jerk;
                if (!(limit > 0.0)) continue;
                limit *= 1.25;
            } else {
                for (Block& b : blocks) b.tolerance *= 1.25;
            }
            const double raised = cycle(p, blocks);
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
    std::printf("| raised by 25 %% | programs | slower | worst slow-down |\n|---|---:|---:|---:|\n");
    for (std::size_t v = 0; v < 4; ++v)
        std::printf("| %s | %d | %d | %.1f %% |\n", names[v], tried[v], slower[v], 100.0 * worst[v]);
    return 0;
}
