#include <firtp/profile.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace firtp {

namespace {

// The box height a step in direction d reaches on axis i when its T1 puts the most loaded axis
// at its limit: |d_i| / max_k (|d_k| / A_k).
double height(const MachineLimits& limits, const AxisVector& d, int i) {
    double t = 0.0;
    for (int k = 0; k < limits.axes; ++k)
        if (limits.axis[k].max_acceleration > 0.0) t = std::max(t, std::abs(d[k]) / limits.axis[k].max_acceleration);
    return t > 0.0 ? std::abs(d[i]) / t : 0.0;
}

}  // namespace

bool SpacingRules::needs_gap(const AxisVector& x, const AxisVector& y) const {
    if (!(t2 > 0.0)) return false;  // no jerk limit: nothing to smooth
    for (int i = 0; i < limits.axes; ++i) {
        if (!(x[i] * y[i] < 0.0)) continue;
        const double j = limits.axis[i].max_jerk;
        if (!(j > 0.0)) continue;
        if (height(limits, x, i) + height(limits, y, i) > j * t2 * (1.0 + 1e-12)) return true;
    }
    return false;
}

double SpacingRules::spacing(const StepShape& x, const StepShape& y) const {
    // Kernels start in the steps' order (each freezes when its kernel starts): a wider y waits
    // for half the difference.
    const double in_order = 0.5 * ((y.box + y.t2) - (x.box + x.t2));
    if (x.box <= 0.0 && x.direction.isZero()) return std::max(0.5 * y.box, in_order);  // no step
    if (y.box <= 0.0 && y.direction.isZero()) return std::max(0.5 * x.box, in_order);
    if (x.t2 != y.t2) return 0.5 * (x.box + x.t2 + y.box + y.t2);
    return 0.5 * (x.box + y.box) + (x.t2 == t2 && needs_gap(x.direction, y.direction) ? t2 : 0.0);
}

ProfileLegs profile_legs(const SpacingRules& rules, const ProfileInput& block, double a, double p, double b) {
    // The steps in order and the speed of the leg after each: in, [a -> p], [p -> b], out.
    std::array<StepShape, 4> steps;
    std::array<double, 3> speed{};
    std::array<int, 3> leg{};  // which of x0, xp, x1 each gap between steps is
    int n = 0;
    steps[n] = block.in;
    if (p != a) {
        speed[n] = a, leg[n] = 0;
        steps[++n] = {std::abs(p - a) * block.alpha, (p > a ? 1.0 : -1.0) * block.u, rules.t2};
    }
    if (b != p) {
        speed[n] = p, leg[n] = n == 0 ? 0 : 1;
        steps[++n] = {std::abs(b - p) * block.alpha, (b > p ? 1.0 : -1.0) * block.u, rules.t2};
    }
    speed[n] = b, leg[n] = n == 0 ? 0 : 2;
    steps[++n] = block.out;
    std::array<double, 3> x{};
    for (int i = 0; i < n; ++i) x[i] = rules.spacing(steps[i], steps[i + 1]);
    // The reserves keep T2 between a neighbour's ramp and this block's boxes across each junction;
    // a jerk gap between the junction step and the next box here does that already. For one leg
    // both junctions' reserves fall into it (with a gap between its two steps, either suffices).
    auto reserved = [&](int i, double reserve) {
        const double boxes = 0.5 * (steps[i].box + steps[i + 1].box);
        return std::max(x[i], boxes + reserve);
    };
    if (n == 1) {
        x[0] = reserved(0, block.in_reserve + block.out_reserve);
    } else {
        x[0] = reserved(0, block.in_reserve);
        x[n - 1] = reserved(n - 1, block.out_reserve);
    }
    x[0] = std::max(x[0], block.entry_elapsed + 0.5 * (steps[1].box + steps[1].t2));
    // Steps further apart than neighbours: boxes of opposite sign on an axis keep T2 between them.
    for (int i = 0; i + 2 <= n; ++i)
        for (int k = i + 2; k <= n; ++k) {
            if (steps[i].t2 != rules.t2 || steps[k].t2 != rules.t2 ||
                !rules.needs_gap(steps[i].direction, steps[k].direction))
                continue;
            double apart = 0.0;
            for (int m = i; m < k; ++m) apart += x[m];
            const double need = 0.5 * (steps[i].box + steps[k].box) + rules.t2;
            if (apart < need) x[i] += need - apart;
        }
    ProfileLegs legs;
    legs.a = a, legs.p = p, legs.b = b;
    // The rest of the length goes to the fastest leg (a rounding shortfall too, so that the legs
    // cover the block exactly); not to an entry above the cruise and the exit, which is the block
    // entered faster than its own feed and is left at once.
    const double cruise = std::max(p, b);
    auto rank = [&](int i) { return speed[i] <= cruise ? speed[i] : -speed[i]; };
    double used = 0.0;
    int fastest = 0;
    for (int i = 0; i < n; ++i) {
        used += speed[i] * x[i];
        if (rank(i) > rank(fastest)) fastest = i;
    }
    const double extra = block.length - used;
    legs.fits = extra >= -1e-12 * block.length;
    if (legs.fits && extra != 0.0) {
        if (speed[fastest] > 0.0) x[fastest] = std::max(0.0, x[fastest] + extra / speed[fastest]);
        else legs.fits = extra <= 0.0;  // nothing moves: the block cannot be covered
    }
    for (int i = 0; i < n; ++i) (leg[i] == 0 ? legs.x0 : leg[i] == 1 ? legs.xp : legs.x1) += x[i];
    return legs;
}

}  // namespace firtp
