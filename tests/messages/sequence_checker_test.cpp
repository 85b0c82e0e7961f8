// SequenceChecker: exactly once, in order, one program at a time.
#include <firtp/messages.hpp>

#include <gtest/gtest.h>

#include <string>

namespace firtp::messages {
namespace {

using Verdict = SequenceChecker::Verdict;

// Checks, and records the block as queued when accepted (what the component does).
Verdict offer(SequenceChecker& checker, std::int64_t program, std::int64_t seq, bool idle = false) {
    const Verdict verdict = checker.check(program, seq, idle);
    if (verdict == Verdict::accept) checker.accepted(program, seq);
    return verdict;
}

TEST(SequenceChecker, StartsExpectingSeqOne) {
    const SequenceChecker checker;
    EXPECT_EQ(checker.program(), 0);
    EXPECT_EQ(checker.next_seq(), 1);
}

TEST(SequenceChecker, AcceptsInOrder) {
    SequenceChecker checker;
    for (std::int64_t seq = 1; seq <= 100; ++seq) ASSERT_EQ(offer(checker, 7, seq, seq == 1), Verdict::accept);
    EXPECT_EQ(checker.program(), 7);
    EXPECT_EQ(checker.next_seq(), 101);
}

TEST(SequenceChecker, CheckAloneChangesNothing) {
    SequenceChecker checker;
    EXPECT_EQ(checker.check(7, 1, true), Verdict::accept);
    EXPECT_EQ(checker.check(7, 1, true), Verdict::accept);  // not queued (e.g. queue full): still expected
    EXPECT_EQ(checker.program(), 0);
    EXPECT_EQ(checker.next_seq(), 1);
}

TEST(SequenceChecker, RepeatedIsRefused) {
    SequenceChecker checker;
    for (std::int64_t seq = 1; seq <= 5; ++seq) offer(checker, 7, seq, seq == 1);
    EXPECT_EQ(offer(checker, 7, 5), Verdict::repeated);
    EXPECT_EQ(offer(checker, 7, 1), Verdict::repeated);
    EXPECT_EQ(offer(checker, 7, 1, true), Verdict::repeated);  // same program, even when idle
    EXPECT_EQ(checker.next_seq(), 6);
}

TEST(SequenceChecker, GapIsRefusedUntilTheMissingOneArrives) {
    SequenceChecker checker;
    for (std::int64_t seq = 1; seq <= 3; ++seq) offer(checker, 7, seq, seq == 1);
    EXPECT_EQ(offer(checker, 7, 6), Verdict::gap);
    EXPECT_EQ(offer(checker, 7, 5), Verdict::gap);
    EXPECT_EQ(checker.next_seq(), 4);
    EXPECT_EQ(offer(checker, 7, 4), Verdict::accept);
    EXPECT_EQ(offer(checker, 7, 5), Verdict::accept);
}

// 4 and 5 swapped on the way: 5 is a gap, 4 is accepted, the host resends 5 (accepted), and the
// late copy of 5 that the network still delivers is a repeat.
TEST(SequenceChecker, ReorderingIsGapThenMissingThenRepeat) {
    SequenceChecker checker;
    for (std::int64_t seq = 1; seq <= 3; ++seq) offer(checker, 7, seq, seq == 1);
    EXPECT_EQ(offer(checker, 7, 5), Verdict::gap);
    EXPECT_EQ(offer(checker, 7, 4), Verdict::accept);
    EXPECT_EQ(offer(checker, 7, 5), Verdict::accept);
    EXPECT_EQ(offer(checker, 7, 5), Verdict::repeated);
    EXPECT_EQ(offer(checker, 7, 6), Verdict::accept);
    EXPECT_EQ(checker.next_seq(), 7);
}

TEST(SequenceChecker, NewProgramWhileBusy) {
    SequenceChecker checker;
    for (std::int64_t seq = 1; seq <= 3; ++seq) offer(checker, 7, seq, seq == 1);
    EXPECT_EQ(offer(checker, 8, 1, false), Verdict::busy);
    EXPECT_EQ(offer(checker, 8, 2, false), Verdict::busy);
    EXPECT_EQ(checker.program(), 7);
    EXPECT_EQ(offer(checker, 7, 4, false), Verdict::accept);  // the running program goes on
}

TEST(SequenceChecker, NewProgramWhenIdle) {
    SequenceChecker checker;
    for (std::int64_t seq = 1; seq <= 3; ++seq) offer(checker, 7, seq, seq == 1);
    EXPECT_EQ(offer(checker, 8, 2, true), Verdict::gap);  // a new program starts at 1
    EXPECT_EQ(offer(checker, 8, 0, true), Verdict::repeated);
    EXPECT_EQ(offer(checker, 8, 1, true), Verdict::accept);
    EXPECT_EQ(checker.program(), 8);
    EXPECT_EQ(checker.next_seq(), 2);
    EXPECT_EQ(offer(checker, 8, 2), Verdict::accept);
}

TEST(SequenceChecker, LateCopyOfAnEarlierProgramIsARepeatEvenWhenIdle) {
    SequenceChecker checker;
    for (std::int64_t seq = 1; seq <= 3; ++seq) offer(checker, 7, seq, seq == 1);
    ASSERT_EQ(offer(checker, 9, 1, true), Verdict::accept);
    EXPECT_EQ(offer(checker, 7, 1, true), Verdict::repeated);  // would run program 7's first block again
    EXPECT_EQ(checker.program(), 9);
    EXPECT_EQ(checker.next_seq(), 2);
}

TEST(SequenceChecker, FirstProgramMayUseIdZero) {
    SequenceChecker checker;
    EXPECT_EQ(offer(checker, 0, 1, false), Verdict::accept);  // already the current program
    EXPECT_EQ(offer(checker, 0, 2, false), Verdict::accept);
}

TEST(SequenceChecker, DescribesEveryVerdict) {
    for (auto verdict : {Verdict::accept, Verdict::repeated, Verdict::gap, Verdict::busy})
        EXPECT_FALSE(std::string(SequenceChecker::describe(verdict)).empty());
    EXPECT_NE(std::string(SequenceChecker::describe(Verdict::gap)).find("gap"), std::string::npos);
    EXPECT_NE(std::string(SequenceChecker::describe(Verdict::busy)).find("busy"), std::string::npos);
}

}  // namespace
}  // namespace firtp::messages
