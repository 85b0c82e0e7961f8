// firtp's planning core in one page: two blocks that meet at a right-angled corner, blended
// within 0.1 mm, run by a servo loop as a servo thread would (docs/API.md).
//
// Built with the project (build/bin/firtp_api_01_corner); ctest runs it (api.01_corner). It
// prints a few samples and exits 1 unless the tool ends exactly on the last block's end point and
// passed the corner within its tolerance without stopping.
#include <firtp/planner.hpp>

#include <algorithm>
#include <cstdio>
#include <limits>

using namespace firtp;

namespace {

// Distance from point p to the segment a-b (the tool's straight path between two samples).
double to_segment(const AxisVector& p, const AxisVector& a, const AxisVector& b) {
    const AxisVector d = b - a;
    const double length2 = d.squaredNorm();
    const double u = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    return (a + u * d - p).norm();
}

}  // namespace

int main() {
    // The machine: X Y Z at 300 mm/s, 5000 mm/s^2 and 100000 mm/s^3, a 1 ms servo period. Every
    // velocity change is smoothed at these limits (the default, limit-driven mode).
    PlannerParameters parameters;
    parameters.period = 0.001;
    parameters.limits.axes = 3;
    for (int a = 0; a < 3; ++a) parameters.limits.axis[a] = {300.0, 5000.0, 1e5};
    Planner planner(parameters, AxisVector::Zero());

    // The program: 20 mm along X at 100 mm/s, then 20 mm along Y; the corner at (20, 0) blends
    // within 0.1 mm (the tolerance of the block that ends there). (Within 0.05 mm the corner
    // would pass at 5.7 mm/s and lose more time than a stop: the planner stops there.)
    Block first;
    first.target[0] = 20.0;
    first.feed = 100.0;
    first.tolerance = 0.1;
    first.line = 1;
    Block second = first;
    second.target[1] = 20.0;
    second.line = 2;
    for (const Block& block : {first, second})
        if (const Result result = planner.add(block); result != Result::ok) {
            std::fprintf(stderr, "line %lld: %s\n", static_cast<long long>(block.line), planner.refusal());
            return 1;
        }

    // The servo loop: one update a period until the motion is finished.
    PlannerInput input;
    input.end_of_program = true;  // nothing follows these two blocks
    PlannerOutput output;
    AxisVector previous = AxisVector::Zero();
    const AxisVector corner = first.target;
    double corner_error = std::numeric_limits<double>::infinity();
    double speed_at_corner = 0.0;
    for (long period = 0;; ++period) {
        const Result result = planner.update(input, output);
        const AxisState& s = output.state;
        const double error = to_segment(corner, previous, s.position);
        if (error < corner_error) corner_error = error, speed_at_corner = s.velocity.norm();
        previous = s.position;
        if (period % 100 == 0 || result == Result::finished)
            std::printf("t %.3f s  line %lld  x %8.4f  y %8.4f  speed %7.2f mm/s\n", s.time,
                        static_cast<long long>(s.line), s.position[0], s.position[1], s.velocity.norm());
        if (result == Result::finished) break;
    }

    const bool at_end = output.state.position == second.target;  // exactly: no drift
    const bool within = corner_error <= first.tolerance;
    std::printf("end %s; corner passed %.4f mm from (20, 0) (tolerance %.2f mm) at %.1f mm/s\n",
                at_end ? "exactly on (20, 20)" : "NOT on (20, 20)", corner_error, first.tolerance, speed_at_corner);
    return at_end && within && speed_at_corner > 0.0 ? 0 : 1;
}
