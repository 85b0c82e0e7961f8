// The guided searches (search.hpp) against the plain bisection they replay: bit for bit the same
// answer for monotone tests, far fewer tests, and a passing answer where the test is not monotone.
#include <firtp/search.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

using namespace firtp;

namespace {

// A block-like test: the length a speed v needs, v (c + k v) (+ a jump where a ramp appears),
// against the length available; passes while the margin is >= 0.
struct BlockTest {
    double length = 10.0, c = 0.05, k = 1e-4, jump_at = 1e300, jump = 0.0;
    int* count = nullptr;
    double margin(double v) const { return length - v * (c + k * v) - (v > jump_at ? jump : 0.0); }
    search::Probe operator()(double v) const {
        if (count != nullptr) ++*count;
        const double m = margin(v);
        return {m >= 0.0, m};
    }
};

TEST(Search, GuidedHighestIsTheBisectionsAnswer) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long guided_tests = 0, plain_tests = 0;
    for (int n = 0; n < 20000; ++n) {
        BlockTest t;
        t.length = 0.1 + 40.0 * unit(rng);
        t.c = 0.001 + 0.1 * unit(rng);
        t.k = 1e-5 + 1e-3 * unit(rng);
        if (n % 3 == 1) t.jump_at = 300.0 * unit(rng), t.jump = 5.0 * unit(rng);  // the flip may sit on it
        const double lo = n % 5 == 0 ? 0.0 : 50.0 * unit(rng), hi = lo + 300.0 * unit(rng);
        int guided = 0, plain = 0;
        BlockTest g = t, p = t;
        g.count = &guided, p.count = &plain;
        const double a = search::highest(g, lo, hi);
        const double b = search::highest([&](double v) { return p(v).ok; }, lo, hi);
        ASSERT_EQ(a, b) << "case " << n;
        // Counted, not timed. Where the margin jumps at the flip the guide cannot help: ITP, the
        // replay and the last test then cost a few tests more than bisection.
        ASSERT_LE(guided, plain + 8) << "case " << n;
        if (n % 3 != 1 && b > lo && b < hi) guided_tests += guided, plain_tests += plain;
    }
    EXPECT_LT(guided_tests * 3, plain_tests);  // the guide pays: about 4 times fewer tests
}

TEST(Search, GuidedLowestIsTheBisectionsAnswer) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long guided_tests = 0, plain_tests = 0;
    for (int n = 0; n < 20000; ++n) {
        // Passes from a threshold on: the margin grows with v.
        const double root = 300.0 * unit(rng), slope = 0.01 + unit(rng), curve = 1e-3 * unit(rng);
        const bool jumps = n % 3 == 1;
        int guided = 0, plain = 0;
        auto test = [&](double v, int& count) {
            ++count;
            const double m = (v - root) * (slope + curve * v) + (jumps && v > root ? 1.0 : 0.0);
            return search::Probe{m >= 0.0, m};
        };
        const double lo = 300.0 * unit(rng) * unit(rng), hi = lo + 300.0 * unit(rng);
        const double a = search::lowest([&](double v) { return test(v, guided); }, lo, hi);
        const double b = search::lowest([&](double v) { return test(v, plain).ok; }, lo, hi);
        ASSERT_EQ(a, b) << "case " << n;
        ASSERT_LE(guided, plain + 8) << "case " << n;
        if (!jumps && b > lo && b < hi) guided_tests += guided, plain_tests += plain;
    }
    EXPECT_LT(guided_tests * 3, plain_tests);
}

// The Tk searches' test: passes up to the flip; its margin smooth, or jumping there (jumps).
auto tk_test(double flip, double slope, bool jumps) {
    return [=](double tk, int& count) {
        ++count;
        const double m = (flip - tk) * (slope + tk) - (jumps && tk > flip ? 1.0 : 0.0);
        return search::Probe{m >= 0.0, m};
    };
}

// 12 plain halvings of [lo, hi] keeping the passing half.
template <class T>
double twelve_halvings(T& test, double lo, double hi, int& count) {
    for (int i = 0; i < 12; ++i) {
        const double mid = 0.5 * (lo + hi);
        (test(mid, count).ok ? lo : hi) = mid;
    }
    return lo;
}

// The paper's Tk search: 12 halvings from a passing lo (hi not tested), as PaperPlanner::search.
TEST(Search, GuidedHalvingsAreTheHalvingsAnswer) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long guided_tests = 0, plain_tests = 0;
    for (int n = 0; n < 20000; ++n) {
        const double hi = 0.05 + 0.3 * unit(rng), flip = hi * (1.2 * unit(rng) - 0.1), slope = 0.5 + unit(rng);
        const bool jumps = n % 4 == 1;
        int guided = 0, plain = 0;
        auto test = tk_test(flip, slope, jumps);
        const double lo = 0.0, m_lo = test(lo, guided).margin;
        if (!(m_lo >= 0.0)) continue;  // lo must pass
        const double a = search::halvings([&](double tk) { return test(tk, guided); }, lo, m_lo, hi, 12);
        ASSERT_EQ(a, twelve_halvings(test, lo, hi, plain)) << "case " << n;
        ASSERT_LE(guided, plain + 1 + 8) << "case " << n;  // + the test of lo
        if (!jumps && flip > lo && flip < hi) guided_tests += guided - 1, plain_tests += plain;
    }
    EXPECT_LT(guided_tests * 4, plain_tests * 3);  // 12 halvings leave less to save: about a quarter
}

// The same halvings where hi is known to fail (PaperPlanner::search's estimate): the answer is
// the halvings', and a flip near the top (counted) costs a few tests instead of walking up to it.
TEST(Search, HalvingsFromAFailedHiAreTheHalvingsAnswer) {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long guided_tests = 0, plain_tests = 0, one_end_tests = 0;
    for (int n = 0; n < 20000; ++n) {
        const double lo = 0.05 * unit(rng), hi = lo + 0.01 + 0.3 * unit(rng), slope = 0.5 + unit(rng);
        // Near the top in most cases, as an estimate just above the flip leaves it.
        const double flip = n % 2 == 0 ? hi - (hi - lo) * 0.01 * unit(rng) : lo + (hi - lo) * unit(rng);
        const bool jumps = n % 4 == 1;
        int guided = 0, plain = 0;
        auto test = tk_test(flip, slope, jumps);
        const search::Probe at_lo = test(lo, guided), at_hi = test(hi, guided);
        if (!at_lo.ok || at_hi.ok) continue;
        const double a = search::halvings([&](double tk) { return test(tk, guided); }, lo, at_lo.margin, hi, at_hi.margin, 12);
        ASSERT_EQ(a, twelve_halvings(test, lo, hi, plain)) << "case " << n;
        ASSERT_LE(guided, plain + 2 + 8) << "case " << n;  // + the tests of lo and hi
        int one_end = 0;  // the halvings from lo alone
        ASSERT_EQ(search::halvings([&](double tk) { return test(tk, one_end); }, lo, at_lo.margin, hi, 12), a);
        if (!jumps && n % 2 == 0) guided_tests += guided - 2, plain_tests += plain, one_end_tests += one_end;
    }
    std::printf("near the top: %ld tests, from lo alone %ld, plain halvings %ld\n", guided_tests, one_end_tests, plain_tests);
    EXPECT_LT(guided_tests * 3, plain_tests * 2);
    EXPECT_LT(guided_tests * 3, one_end_tests * 2);
}

// highest() with a guess of the flip (max_entry: the exit bound a short block keeps, where the
// test's margin jumps): the same answer as highest() whether the guess is right, near or wrong,
// and where it is right, a few tests instead of bisection's 48.
TEST(Search, HighestFromAGuessIsHighestsAnswer) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long right_tests = 0, right_plain = 0, cases = 0;
    for (int n = 0; n < 20000; ++n) {
        const double hi = 1.0 + 400.0 * unit(rng), flip = hi * unit(rng);
        const int kind = n % 4;  // guess: at the flip, a hair below it, far off, outside the range
        const double guess = kind == 0 ? flip : kind == 1 ? flip * (1.0 - 1e-15) : kind == 2 ? hi * unit(rng) : hi * 1.5;
        int guided = 0, plain = 0;
        // A margin that jumps at the flip (the block cannot brake from above it).
        auto test = [&](double v, int& count) {
            ++count;
            const double m = v <= flip ? 0.5 + (flip - v) : -1.0 - (v - flip);
            return search::Probe{m >= 0.0, m};
        };
        const double a = search::highest([&](double v) { return test(v, guided); }, 0.0, hi, guess);
        const double b = search::highest([&](double v) { return test(v, plain).ok; }, 0.0, hi);
        ASSERT_EQ(a, b) << "case " << n;
        if (kind == 0) right_tests += guided, right_plain += plain, ++cases;
    }
    std::printf("guess at the flip: %.1f tests a search, bisection %.1f\n", static_cast<double>(right_tests) / static_cast<double>(cases),
                static_cast<double>(right_plain) / static_cast<double>(cases));
    EXPECT_LT(right_tests * 5, right_plain);
}

// A guess found in closed form, to rounding: the same answer as bisection, whether the guess is
// right, a few ulps either side, far off or outside the range; about four tests where it is right.
TEST(Search, HighestNearIsTheBisectionsAnswer) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long right_tests = 0, right_plain = 0, cases = 0;
    for (int n = 0; n < 40000; ++n) {
        const double hi = 1.0 + 400.0 * unit(rng);
        const double flip = n % 50 == 0 ? hi * 2.0 : hi * std::ldexp(unit(rng), -static_cast<int>(rng() % 12));
        const int kind = n % 5;  // guess: at the flip, 4 ulps below, 4 above, far off, outside the range
        const double ulps = 4.0 * std::numeric_limits<double>::epsilon() * flip;
        const double guess = kind == 0 ? flip : kind == 1 ? flip - ulps : kind == 2 ? flip + ulps : kind == 3 ? hi * unit(rng) : hi * 1.5;
        int near = 0, plain = 0;
        auto test = [&](double v, int& count) {
            ++count;
            const double m = (flip - v) / hi;  // smooth: ITP's case
            return search::Probe{v <= flip, m};
        };
        const double a = search::highest_near([&](double v) { return test(v, near); }, 0.0, hi, guess);
        const double b = search::highest([&](double v) { return test(v, plain).ok; }, 0.0, hi);
        ASSERT_EQ(a, b) << "case " << n << " guess kind " << kind;
        if (kind == 0 && flip < hi) right_tests += near, right_plain += plain, ++cases;
    }
    std::printf("closed-form guess: %.2f tests a search, bisection %.1f\n", static_cast<double>(right_tests) / static_cast<double>(cases),
                static_cast<double>(right_plain) / static_cast<double>(cases));
    EXPECT_LE(right_tests, 5 * cases);
}

// Tests that pass nowhere in the range, or only in its first 2^-9 .. 2^-47: the bisection's answer
// (lo, or where the flip is), and where none passes, a few tests instead of bisection's 48 (+1).
TEST(Search, NowhereOrNearTheKeptEndIsTheBisectionsAnswer) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 4000; ++n) {
        const double lo = n % 2 == 0 ? 0.0 : 100.0 * unit(rng), hi = lo + 1.0 + 300.0 * unit(rng);
        const bool nowhere = n % 3 == 0;
        const double flip = nowhere ? lo - 1.0 : lo + (hi - lo) * std::ldexp(0.5 + 0.5 * unit(rng), -9 - static_cast<int>(rng() % 39));
        for (bool up : {true, false}) {
            // Up: passes up to the flip (highest); else passes from its mirror on (lowest).
            const double at = up ? flip : hi - (flip - lo);
            int guided = 0, plain = 0;
            auto test = [&](double v, int& count) {
                ++count;
                const double m = up ? at - v : v - at;
                return search::Probe{m >= 0.0, m};
            };
            const double a = up ? search::highest([&](double v) { return test(v, guided); }, lo, hi)
                                : search::lowest([&](double v) { return test(v, guided); }, lo, hi);
            const double b = up ? search::highest([&](double v) { return test(v, plain).ok; }, lo, hi)
                                : search::lowest([&](double v) { return test(v, plain).ok; }, lo, hi);
            ASSERT_EQ(a, b) << "case " << n << (up ? " highest" : " lowest");
            if (nowhere) {
                EXPECT_EQ(a, up ? lo : hi);
                EXPECT_GE(plain, 40) << "case " << n;  // (halvings to 1e-13 of hi)
                EXPECT_LE(guided, 1 + search::nowhere_after + 1) << "case " << n;
            } else {
                // A flip within 2^-40 of the kept end: bisection reaches it only at its last halvings,
                // where ITP and the replay cost up to 10 tests more; the test of the last halving
                // point one more.
                EXPECT_LE(guided, plain + 11) << "case " << n;
            }
        }
    }
}

// Not monotone: passes on [0, 100] and again on [150, 151]; the margin points at 150.5. The answer
// need not be the bisection's, but it passes.
TEST(Search, NotMonotoneStillPasses) {
    auto margin = [](double v) { return v <= 100.0 ? 100.0 - v : std::abs(v - 150.5) <= 0.5 ? 0.5 - std::abs(v - 150.5) : -1.0; };
    for (double hi : {160.0, 170.0, 200.0, 151.2, 300.0}) {
        const double v = search::highest([&](double x) { return search::Probe{margin(x) >= 0.0, margin(x)}; }, 0.0, hi);
        EXPECT_GE(margin(v), 0.0) << hi;
    }
}

}  // namespace
