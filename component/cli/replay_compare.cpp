#include "replay_compare.hpp"

#include <algorithm>
#include <cmath>

namespace firtp::cli {
namespace {

bool at_rest(const firtp_lcm::axis_state_t& s, int axes) {
    if (s.line != 0) return false;
    for (int a = 0; a < axes; ++a)
        if (s.velocity[a] != 0.0 || s.acceleration[a] != 0.0) return false;
    return true;
}

std::size_t next_moving(const std::vector<firtp_lcm::axis_state_t>& states, std::size_t i, int axes) {
    while (i < states.size() && at_rest(states[i], axes)) ++i;
    return i;
}

class Comparer {
public:
    Comparer(int axes, double tolerance) : axes_(axes), tolerance_(tolerance) {}

    // False at the first difference (kept in result).
    bool values(const char* what, const double (&r)[9], const double (&p)[9], std::size_t i, std::size_t j) {
        for (int a = 0; a < axes_; ++a) {
            const double d = std::fabs(r[a] - p[a]);
            if (d > result.largest || std::isnan(d)) result.largest = d;
            if (!(d <= tolerance_ * std::max(1.0, std::fabs(r[a])))) {
                result.first = StateDifference{i, j, what, a, r[a], p[a]};
                return false;
            }
        }
        return true;
    }
    bool state(const firtp_lcm::axis_state_t& r, const firtp_lcm::axis_state_t& p, std::size_t i, std::size_t j) {
        if (!values("position", r.position, p.position, i, j) || !values("velocity", r.velocity, p.velocity, i, j) ||
            !values("acceleration", r.acceleration, p.acceleration, i, j))
            return false;
        if (r.line != p.line) {
            result.first = StateDifference{i, j, "line", -1, double(r.line), double(p.line)};
            return false;
        }
        ++result.compared;
        return true;
    }

    Comparison result;

private:
    int axes_;
    double tolerance_;
};

}  // namespace

Comparison compare_states(const std::vector<firtp_lcm::axis_state_t>& recorded,
                          const std::vector<firtp_lcm::axis_state_t>& replayed, int axes, double tolerance) {
    Comparer c(axes, tolerance);
    std::size_t i = 0, j = 0;
    while (i < recorded.size() && j < replayed.size()) {
        if (at_rest(recorded[i], axes) && at_rest(replayed[j], axes)) {
            if (!c.values("position", recorded[i].position, replayed[j].position, i, j)) break;
            ++c.result.compared;
            const std::size_t ni = next_moving(recorded, i, axes), nj = next_moving(replayed, j, axes);
            if (ni == recorded.size()) break;  // the recording ends at rest: so far equal
            if (nj == replayed.size()) {       // the recording moves again, the replay does not
                c.result.first = StateDifference{ni, replayed.size() - 1, "motion", -1, 1.0, 0.0};
                break;
            }
            // Rest up to the motion: the same place (the last resting state before it).
            if (ni > i && nj > j && !c.values("position", recorded[ni - 1].position, replayed[nj - 1].position, ni - 1, nj - 1))
                break;
            i = ni;
            j = nj;
            continue;
        }
        if (!c.state(recorded[i], replayed[j], i, j)) break;
        ++i;
        ++j;
    }
    if (!c.result.first && i < recorded.size() && j == replayed.size())  // the replay stopped short
        c.result.first = StateDifference{i, j, "motion", -1, 1.0, 0.0};
    return c.result;
}

}  // namespace firtp::cli
