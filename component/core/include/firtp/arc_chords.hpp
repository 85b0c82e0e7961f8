// Where an arc's chords end, as fractions of the arc: the G-code reader (G2/G3, helices) and
// firtp_tp (tpAddCircle) both chord arcs with this.
//
// An arc of n chords within the chord tolerance is cut at k / n, and its first and last chords
// once more into pieces of 1/8, 1/8, 1/4 and 1/2 of a chord, the shortest at the arc's ends. A
// corner where the arc meets a line (or another arc) is passed slowly, and a run of chords changes
// speed only where two chords meet (lookahead.hpp): the chord next to the corner ran at the
// corner's speed for its whole length. Shorter there, the run speeds up sooner after the corner
// and slows down later before it (examples/arcs.ngc at jerk 1e5: 6.55 -> 6.26 s,
// docs/BENCHMARKS.md). Every piece ends on the arc, so no chord strays further from it than a
// chord of n uniform ones does. The paper's fixed chain keeps the n equal chords: a pulse shorter
// than its filters lowers its feed (paper_planner.hpp), and its arcs run at one capped speed.
#pragma once

namespace firtp {

// Pieces each end chord is cut into: 1/8, 1/8, 1/4, 1/2 of a chord.
inline constexpr int arc_end_pieces = 4;

// Chords of an arc that n uniform chords keep within the tolerance (n >= 1); `cut_ends` false
// (the paper's fixed chain): n. One chord stays one.
constexpr int graded_chord_count(int n, bool cut_ends = true) { return cut_ends && n >= 2 ? n + 2 * (arc_end_pieces - 1) : n; }

// The fraction of the arc where chord k of graded_chord_count(n, cut_ends) ends (k = 0: 0).
constexpr double graded_chord_end(int k, int n, bool cut_ends = true) {
    const int total = graded_chord_count(n, cut_ends);
    if (k <= 0) return 0.0;
    if (k >= total) return 1.0;
    if (total == n) return static_cast<double>(k) / n;
    // Where the first chord's pieces end, in chords: 1/8, 1/4, 1/2, 1.
    constexpr double piece_end[arc_end_pieces] = {0.125, 0.25, 0.5, 1.0};
    if (k <= arc_end_pieces) return piece_end[k - 1] / n;
    const int from_end = total - k;  // pieces of the last chord still to come
    if (from_end < arc_end_pieces) return 1.0 - piece_end[from_end - 1] / n;
    return static_cast<double>(k - arc_end_pieces + 1) / n;
}

}  // namespace firtp
