// The planner's one-dimensional searches: the highest (or lowest) speed a test passes.
//
// The answer is defined by bisection: 48 halvings at most, to 1e-13 of the upper end. A test that
// also says by how much it passes (Probe::margin, the length left over in a block) lets the search
// find where it flips first (ITP, a safeguarded regula falsi: about ten tests where bisection
// makes 45) and then replay the bisection's halvings against that bracket: a halving point at or
// below the last passing speed passes, one at or above the first failing speed fails, and only
// points inside the bracket are tested. For a test that is monotone that is the bisection's
// answer, bit for bit. The answer is tested once more where it was only inferred; if it fails (a
// test that is not monotone there), the plain bisection decides. Where the margin jumps at the
// flip, the guide cannot help: a few tests more than bisection (search_test.cpp holds it to 8; 11
// where the flip lies in bisection's last halvings). After a run of failures the search asks
// whether the last point bisection would test passes at all: where it does not, the answer is the
// kept end after a dozen tests instead of 49.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>

namespace firtp::search {

constexpr int bisection_steps = 48;
constexpr int nowhere_after = 8;  // failed halvings before flip() asks whether any point passes
constexpr double resolution = 1e-13;  // of the upper end

struct Probe {
    bool ok = false;
    double margin = 0.0;  // >= 0 about where ok; a guide only (ok decides)
};

// Narrows [x_ok, x_bad] (either order) to 2 eps by the ITP method (Oliveira and Takahashi, ACM
// TOMS 47(1), 2020) on the margins: regula falsi, truncated and projected so that it never needs
// more than one test beyond bisection's count, superlinear where the margin is smooth.
template <class F>
void narrow(F& probe, double& x_ok, double m_ok, double& x_bad, double m_bad, double eps) {
    const bool ok_low = x_ok < x_bad;
    double a = ok_low ? x_ok : x_bad, b = ok_low ? x_bad : x_ok;
    double ya = ok_low ? m_ok : m_bad, yb = ok_low ? m_bad : m_ok;
    if (!(b - a > 2.0 * eps)) return;
    const double k1 = 0.2 / (b - a);  // the method's kappa_1; kappa_2 = 2, n_0 = 1
    const int n_max = static_cast<int>(std::ceil(std::log2((b - a) / (2.0 * eps)))) + 1;
    double reach = eps * std::ldexp(1.0, n_max);  // eps 2^(n_max - j): halved each step, exactly
    for (int j = 0; j < n_max && b - a > 2.0 * eps; ++j, reach *= 0.5) {
        const double half = 0.5 * (a + b);
        const double r = reach - 0.5 * (b - a);
        const double delta = std::max(k1 * (b - a) * (b - a), eps);  // past a flip found to rounding
        double falsi = half;
        if ((ya >= 0.0) != (yb >= 0.0)) falsi = (yb * a - ya * b) / (yb - ya);
        if (!std::isfinite(falsi)) falsi = half;
        const double sigma = half >= falsi ? 1.0 : -1.0;
        const double truncated = delta <= std::abs(half - falsi) ? falsi + sigma * delta : half;
        double x = std::abs(truncated - half) <= r ? truncated : half - sigma * r;
        if (!(x > a && x < b)) x = half;
        if (!(x > a && x < b)) break;  // a and b adjacent doubles
        const Probe p = probe(x);
        if (p.ok == ok_low) a = x, ya = p.margin;
        else b = x, yb = p.margin;
    }
    x_ok = ok_low ? a : b;
    x_bad = ok_low ? b : a;
}

// Half the bisection's resolution near a flip between l and h (>= 0): at most a factor 2 finer
// than needed where the flip is above the middle (a replayed halving tests what this leaves).
inline double flip_eps(double l, double h) {
    const double small = std::min(std::abs(l), std::abs(h)), large = std::max(std::abs(l), std::abs(h));
    return 0.5 * resolution * std::max(small, 0.5 * large);
}

// Of a bisection's bracket [l, h]: the end a halving keeps on a pass (Up: l, the answer of
// highest()), and the other.
template <bool Up>
double& kept(double& l, double& h) {
    return Up ? l : h;
}
template <bool Up>
double& other(double& l, double& h) {
    return Up ? h : l;
}

// The rest of a guided bisection. From halving i on, with [l, h] as the halvings left it, and
// x_ok passing (margin m_ok), x_bad failing (m_bad) within it: the flip narrowed to 2 eps by ITP,
// then the halvings replayed on that bracket while more(i, l, h), testing only points inside it.
// The kept end at the close, tested once more where it was only inferred (kept_tested: whether the
// kept end it starts from passed a test); none where that test fails (not monotone there: the
// caller's plain bisection decides).
template <bool Up, class F, class More>
std::optional<double> replay(F& test, double l, double h, int i, More&& more, bool kept_tested, double x_ok, double m_ok,
                             double x_bad, double m_bad, double eps) {
    narrow(test, x_ok, m_ok, x_bad, m_bad, eps);
    bool tested = kept_tested;  // the kept end passed a test (not inferred)
    for (; more(i, l, h); ++i) {
        const double mid = 0.5 * (l + h);
        bool pass = false, known = true;
        if (Up ? mid <= x_ok : mid >= x_ok) pass = true, known = false;
        else if (Up ? mid >= x_bad : mid <= x_bad) pass = false;
        else if ((pass = test(mid).ok)) x_ok = mid;
        else x_bad = mid;
        if (pass) kept<Up>(l, h) = mid, tested = known;
        else other<Up>(l, h) = mid;
    }
    if (tested || test(kept<Up>(l, h)).ok) return kept<Up>(l, h);
    return std::nullopt;
}

// The same where the kept end passed (m_ok) and the other failed (m_bad).
template <bool Up, class F, class More>
std::optional<double> replay(F& test, double l, double h, int i, More&& more, double m_ok, double m_bad, double eps) {
    return replay<Up>(test, l, h, i, more, true, kept<Up>(l, h), m_ok, other<Up>(l, h), m_bad, eps);
}

namespace detail {

// flip()'s halvings: 48 at most, to `resolution` of the upper end.
inline bool more(int i, double l, double h) { return i < bisection_steps && h - l > resolution * h; }

// Plain bisection of [l, h] while more(i, l, h): the kept end.
template <bool Up, class F, class More = decltype(more)&>
double bisect(F& ok, double l, double h, More&& more = detail::more) {
    for (int i = 0; more(i, l, h); ++i) {
        const double mid = 0.5 * (l + h);
        (ok(mid) ? kept<Up>(l, h) : other<Up>(l, h)) = mid;
    }
    return kept<Up>(l, h);
}

// A replayed guided search's answer, or, where it found the test not monotone (none), plain
// bisection of [lo, hi] while more(): the fallback every guided search shares.
template <bool Up, class F, class More>
double or_bisection(F& test, double lo, double hi, More&& more, const std::optional<double>& answer) {
    if (answer) return *answer;
    auto ok = [&](double x) { return test(x).ok; };
    return bisect<Up>(ok, lo, hi, more);
}

// flip()'s guided search once the end it tests first has failed; x_bad (margin m_bad) is the
// failing point nearest the other end known so far (that end itself if nothing more is known).
template <bool Up, class F>
double guided_flip(F& test, double lo, double hi, double x_bad, double m_bad) {
    auto known_bad = [&](double x) { return Up ? x >= x_bad : x <= x_bad; };
    // The bisection itself up to its first passing point (the other end is never tested)...
    double l = lo, h = hi, m_ok = 0.0;
    int i = 0;
    bool found = false;
    for (; more(i, l, h) && !found; ++i) {
        // After a run of failures, the last point the halvings would reach: where it fails
        // too, no halving point passes (the kept end is the answer, untested as bisection
        // leaves it). Some searches pass nowhere (a block too short to start and stop in:
        // 64 % of lcnc__tort.ngc's), and bisection tests 48 points to say so.
        if (i == nowhere_after) {
            double el = l, eh = h, last = 0.0;
            bool any = false;
            for (int k = i; more(k, el, eh); ++k) last = other<Up>(el, eh) = 0.5 * (el + eh), any = true;
            if (any && (known_bad(last) || !test(last).ok)) return kept<Up>(l, h);
        }
        const double mid = 0.5 * (l + h);
        if (known_bad(mid)) {
            other<Up>(l, h) = mid;
            continue;
        }
        const Probe p = test(mid);
        if (p.ok) kept<Up>(l, h) = mid, m_ok = p.margin, found = true;
        else other<Up>(l, h) = mid, x_bad = mid, m_bad = p.margin;
    }
    if (!found) return kept<Up>(l, h);
    // ... then the rest on the flip.
    return or_bisection<Up>(test, lo, hi, more,
                            replay<Up>(test, l, h, i, more, true, kept<Up>(l, h), m_ok, x_bad, m_bad, flip_eps(l, h)));
}

// highest()'s answer from a passing x_ok and a failing x_bad (margins m_ok, m_bad), hi failing:
// the flip narrowed to 2 eps, the halvings replayed on it; plain bisection where that is not
// monotone.
template <class F>
double highest_within(F& test, double lo, double hi, double x_ok, double m_ok, double x_bad, double m_bad, double eps) {
    return or_bisection<true>(test, lo, hi, more,
                              replay<true>(test, lo, hi, 0, more, false, x_ok, m_ok, x_bad, m_bad, eps));
}

}  // namespace detail

// Where ok flips in [lo, hi]. Up: ok true up to the flip, false beyond; the largest x that passes
// (lo if none). Not Up: ok false up to it, true beyond; the smallest (hi if none). `test` returns
// bool (bisection) or Probe (guided, the same answer where the test is monotone).
template <bool Up, class F>
double flip(F&& test, double lo, double hi) {
    constexpr bool guided = std::is_same_v<std::invoke_result_t<F&, double>, Probe>;
    if (!(hi > lo)) return Up ? lo : hi;
    const double end = Up ? hi : lo;  // the end tested first
    if constexpr (!guided) {
        if (test(end)) return end;
        return detail::bisect<Up>(test, lo, hi);
    } else {
        const Probe first = test(end);
        if (first.ok) return end;
        return detail::guided_flip<Up>(test, lo, hi, end, first.margin);
    }
}

// Largest x in [lo, hi] with ok(x), for ok true up to some point and false beyond; lo if none.
template <class F>
double highest(F&& test, double lo, double hi) {
    return flip<true>(test, lo, hi);
}

// highest() where the flip is likely at `guess` (the exit bound a short block keeps: its test's
// margin jumps there and ITP cannot help, so the search was plain bisection, 48 tests): hi, then
// guess and a point 2 eps above it are tested; where those two bracket the flip, bisection's
// halvings are replayed on the bracket (the same answer where the test is monotone, in about five
// tests); else the guided search goes on from what those tests found.
template <class F>
double highest(F&& test, double lo, double hi, double guess) {
    if (!(hi > lo) || !(guess > lo && guess < hi)) return highest(test, lo, hi);
    const Probe top = test(hi);
    if (top.ok) return hi;
    const Probe at = test(guess);
    if (!at.ok) return detail::guided_flip<true>(test, lo, hi, guess, at.margin);
    const double eps = flip_eps(lo, hi), above = guess + 2.0 * eps;
    double x_ok = guess, m_ok = at.margin, x_bad = hi, m_bad = top.margin;
    if (above < hi) {
        const Probe over = test(above);
        if (over.ok) x_ok = above, m_ok = over.margin;
        else x_bad = above, m_bad = over.margin;
    }
    return detail::highest_within(test, lo, hi, x_ok, m_ok, x_bad, m_bad, eps);
}

// highest() where the flip is known to rounding: near x, found in closed form (dense_legs.hpp).
// The points eps either side of x are tested (eps half the bisection's resolution there); where
// they bracket the flip, bisection's halvings are replayed on the bracket: about four tests, hi
// not among them (it fails where the test is monotone). Else the guided search goes on from them.
template <class F>
double highest_near(F&& test, double lo, double hi, double x) {
    const double eps = flip_eps(x, x), below = x - eps, above = x + eps;
    if (!(hi > lo) || !(below > lo && above < hi)) return highest(test, lo, hi);
    const Probe at = test(below);
    if (!at.ok) return detail::guided_flip<true>(test, lo, hi, below, at.margin);
    const Probe over = test(above);
    if (!over.ok) return detail::highest_within(test, lo, hi, below, at.margin, above, over.margin, 0.5 * (above - below));
    const Probe top = test(hi);
    if (top.ok) return hi;
    return detail::highest_within(test, lo, hi, above, over.margin, hi, top.margin, flip_eps(above, hi));
}

// The highest x in [lo, hi] that passes, to 0.05 % of hi: hi where it passes, else halving down
// to a speed that does and narrowing on the margins (narrow). Where none passes within
// 12 halvings, highest (lo where nothing passes).
template <class F>
double about_highest(F&& test, double lo, double hi) {
    const Probe top = test(hi);
    if (top.ok) return hi;
    double x_bad = hi, m_bad = top.margin;
    for (int k = 0; k < 12; ++k) {  // halving down from hi to a speed that passes
        const double x = lo + 0.5 * (x_bad - lo);
        const Probe p = test(x);
        if (p.ok) {
            double x_ok = x;
            narrow(test, x_ok, p.margin, x_bad, m_bad, 5e-4 * hi);
            return x_ok;
        }
        x_bad = x, m_bad = p.margin;
    }
    return highest(test, lo, x_bad);
}

// Smallest x in [lo, hi] with ok(x), for ok false up to some point and true beyond; hi if none.
template <class F>
double lowest(F&& test, double lo, double hi) {
    return flip<false>(test, lo, hi);
}

// `steps` halvings of [lo, hi] keeping the passing half, from lo that passed (margin m_lo; hi not
// tested): where they end, lo if no point passes. Guided as highest(): the halvings up to the first
// failing point, then the rest replayed on the flip.
template <class F>
double halvings(F&& test, double lo, double m_lo, double hi, int steps) {
    auto more = [steps](int i, double, double) { return i < steps; };
    double l = lo, h = hi, m_h = 0.0;
    int i = 0;
    bool failed = false;
    for (; more(i, l, h) && !failed; ++i) {
        const double mid = 0.5 * (l + h);
        const Probe p = test(mid);
        if (p.ok) l = mid, m_lo = p.margin;
        else h = mid, m_h = p.margin, failed = true;
    }
    if (!failed) return l;
    const double eps = 0.25 * std::ldexp(hi - lo, -steps);
    return detail::or_bisection<true>(test, lo, hi, more, replay<true>(test, l, h, i, more, m_lo, m_h, eps));
}

// The same halvings where hi failed its test (margin m_hi): the flip is narrowed from the first
// halving on. Where the flip lies near one end (a good first guess brackets it), the halvings
// that only pass or only fail on the way there cost no tests.
template <class F>
double halvings(F&& test, double lo, double m_lo, double hi, double m_hi, int steps) {
    auto more = [steps](int i, double, double) { return i < steps; };
    const double eps = 0.25 * std::ldexp(hi - lo, -steps);
    return detail::or_bisection<true>(test, lo, hi, more, replay<true>(test, lo, hi, 0, more, m_lo, m_hi, eps));
}

}  // namespace firtp::search
