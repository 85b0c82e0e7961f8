// Built only into core_forced_undo_tests (tests/core/CMakeLists.txt): FIRTP_FORCE_UNDO undoes every
// join spread over periods that passed its check while steps froze, as if no plan had passed. The
// helix chords of Reach then take that rare undo hundreds of times, added as the window takes them
// and one a period (LinuxCNC's feed: the window fills, its blocks gather), and every limit (also in
// 1 ms differences), every corner's tolerance and the exact end must still hold. The undo is
// counted: a run that never reached it could not fail.
#include "support/chords.hpp"
#include "support/rate_run.hpp"
#include "support/sampled_limits.hpp"

#include <firtp/planner.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

using namespace firtp;

TEST(ForcedUndo, HelixChordsKeepEveryLimitThroughTheUndos) {
    const PlannerParameters machine = test::deep_queue_machine();
    const std::vector<Block> program = test::helix_chords(3600);
    const test::RateRun r = test::run_with_rates(machine, program, {}, test::run_ticks(machine));
    test::expect_within(r, program, machine);
    std::printf("%zu chords: %llu joins undone, %llu later join steps\n", program.size(),
                static_cast<unsigned long long>(r.stats.batches_undone), static_cast<unsigned long long>(r.stats.join_steps));
    EXPECT_GT(r.stats.batches_undone, 100u);
}

TEST(ForcedUndo, ChordsFedOneAPeriodKeepEveryLimitThroughTheUndos) {
    PlannerParameters machine = test::deep_queue_machine();
    machine.max_rate = 1.0;
    const std::vector<Block> program = test::helix_chords(1080);
    const test::RateRun r = test::run_with_rates(machine, program, {}, test::run_ticks(machine), 1);
    test::expect_within(r, program, machine);
    std::printf("%zu chords fed one a period: %llu gathered, %llu joins undone\n", program.size(),
                static_cast<unsigned long long>(r.stats.gathered), static_cast<unsigned long long>(r.stats.batches_undone));
    EXPECT_GT(r.stats.gathered, 100u);
    EXPECT_GT(r.stats.batches_undone, 10u);
}
