#include "replay_compare.hpp"

#include <algorithm>
#include <cmath>

namespace firtp::cli {
namespace {

class Comparer {
public:
    Comparer(int axes, double tolerance) : axes_(axes), tolerance_(tolerance) {}

    // False at the first difference (kept in result).
    bool values(const char* what, const double (&r)[9], const double (&p)[9], std::size_t i) {
        for (int a = 0; a < axes_; ++a) {
            const double d = std::fabs(r[a] - p[a]);
            if (d > result.largest || std::isnan(d)) result.largest = d;
            if (!(d <= tolerance_ * std::max(1.0, std::fabs(r[a])))) {
                result.first = StateDifference{i, i, what, a, r[a], p[a]};
                return false;
            }
        }
        return true;
    }
    bool whole(const char* what, std::int64_t r, std::int64_t p, std::size_t i) {
        if (r != p) result.first = StateDifference{i, i, what, -1, double(r), double(p)};
        return r == p;
    }
    bool state(const firtp_lcm::axis_state_t& r, const firtp_lcm::axis_state_t& p, std::size_t i) {
        if (!values("position", r.position, p.position, i) || !values("velocity", r.velocity, p.velocity, i) ||
            !values("acceleration", r.acceleration, p.acceleration, i) || !whole("line", r.line, p.line, i) ||
            !whole("next_seq", r.next_seq, p.next_seq, i) || !whole("control_session", r.control_session, p.control_session, i) ||
            !whole("control_seq", r.control_seq, p.control_seq, i))
            return false;
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
    std::size_t i = 0;
    while (i < recorded.size() && i < replayed.size() && c.state(recorded[i], replayed[i], i)) ++i;
    if (!c.result.first && i < recorded.size())  // the replay stopped short
        c.result.first = StateDifference{i, replayed.size(), "missing", -1, 0.0, 0.0};
    return c.result;
}

}  // namespace firtp::cli
