// arc_chords.hpp: the graded chords of an arc, as fractions of it.
#include <firtp/arc_chords.hpp>

#include <gtest/gtest.h>

using namespace firtp;

// Increasing from 0 to 1; the tolerance's chords inside, each end chord in pieces of 1/8, 1/8,
// 1/4, 1/2 of a chord (shortest at the arc's end), the last mirroring the first.
TEST(ArcChords, EndChordsAreCutIntoPiecesShortestAtTheEnds) {
    EXPECT_EQ(graded_chord_count(1), 1);
    EXPECT_EQ(graded_chord_end(0, 1), 0.0);
    EXPECT_EQ(graded_chord_end(1, 1), 1.0);
    for (int n = 2; n <= 400; ++n) {
        const int total = graded_chord_count(n);
        ASSERT_EQ(total, n + 6);
        ASSERT_EQ(graded_chord_end(0, n), 0.0);
        ASSERT_EQ(graded_chord_end(total, n), 1.0);
        const double chord = 1.0 / n;
        const double pieces[] = {0.125, 0.125, 0.25, 0.5};
        for (int k = 1; k <= total; ++k) {
            const double length = graded_chord_end(k, n) - graded_chord_end(k - 1, n);
            ASSERT_GT(length, 0.0) << n << " " << k;
            double want = chord;
            if (k <= 4) want = pieces[k - 1] * chord;
            if (total - k < 4) want = pieces[total - k] * chord;
            ASSERT_NEAR(length, want, 1e-12) << n << " " << k;
        }
    }
}
