#include <firtp/profile.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace firtp {

namespace {

// The T1 per unit of a step in direction d: max_k |d_k| / A_k. A step in direction d whose T1 puts
// the most loaded axis at its limit reaches the box height |d_i| / that on axis i.
double unit_box(const MachineLimits& limits, const AxisVector& d) {
    double t = 0.0;
    for (int k = 0; k < limits.axes; ++k)
        if (limits.axis[k].max_acceleration > 0.0) t = std::max(t, std::abs(d[k]) / limits.axis[k].max_acceleration);
    return t;
}

double height(double unit_box, const AxisVector& d, int i) { return unit_box > 0.0 ? std::abs(d[i]) / unit_box : 0.0; }

// needs_gap for the directions sx x and sy y (signs of +-1: the products' signs are the same),
// with their unit boxes (< 0: found here when an axis first needs them).
bool gap_between(const SpacingRules& rules, double t2, const AxisVector& x, double sx, double& box_x, const AxisVector& y,
                 double sy, double& box_y) {
    if (!(t2 > 0.0)) return false;  // no jerk limit: nothing to smooth
    for (int i = 0; i < rules.limits.axes; ++i) {
        if (!((sx * x[i]) * (sy * y[i]) < 0.0)) continue;
        const double j = rules.limits.axis[i].max_jerk;
        if (!(j > 0.0)) continue;
        if (box_x < 0.0) box_x = unit_box(rules.limits, x);
        if (box_y < 0.0) box_y = unit_box(rules.limits, y);
        if (height(box_x, x, i) + height(box_y, y, i) > j * t2 * (1.0 + 1e-12)) return true;
    }
    return false;
}

// A step as profile_legs sees it: its shape's numbers, its direction sign * *direction. (No
// default values: profile_legs fills the ones it uses, every call.)
struct StepView {
    double box;
    double t2;
    const AxisVector* direction;
    double sign;
    bool none;      // no step (box 0, no direction)
    double unit_box;
    int role;       // in profile_legs: 0 the entry, 1 a ramp along +u, 2 along -u, 3 the exit (-1: none)
    bool own;       // StepShape::own
    bool gapped;    // StepShape::gapped
};

// (A step at the machine's stage is gapped whoever made it.)
StepView view(const SpacingRules& rules, const StepShape& shape, int role = -1) {
    return {shape.box, shape.t2, &shape.direction, 1.0, shape.box <= 0.0 && shape.direction.isZero(), shape.unit_box, role, shape.own,
            shape.gapped || shape.t2 == rules.t2};
}

// GapMemo's entry for two roles (the gap is symmetric: the same products and sums); -1: none.
int memo_pair(int x, int y) {
    if (x > y) std::swap(x, y);
    static constexpr std::int8_t index[4][4] = {{-1, 0, 1, 2}, {-1, 3, 4, 5}, {-1, -1, 6, 7}, {-1, -1, -1, -1}};
    return x < 0 ? -1 : index[x][y];
}

bool find_gap(const SpacingRules& rules, StepView& x, StepView& y, GapMemo* memo, int k) {
    const bool needed = gap_between(rules, x.t2, *x.direction, x.sign, x.unit_box, *y.direction, y.sign, y.unit_box);
    if (k >= 0) memo->pair[k] = needed ? 2 : 1;
    return needed;
}

// (Small enough to inline where profile_legs asks it: most answers come from the memo.)
inline bool gap(const SpacingRules& rules, StepView& x, StepView& y, GapMemo* memo = nullptr) {
    const int k = memo != nullptr ? memo_pair(x.role, y.role) : -1;
    if (k >= 0 && memo->pair[k] != 0) return memo->pair[k] == 2;
    return find_gap(rules, x, y, memo, k);
}

// SpacingRules::spacing of two views.
double spacing(const SpacingRules& rules, StepView& x, StepView& y, GapMemo* memo = nullptr) {
    // Kernels start in the steps' order (each freezes when its kernel starts): a wider y waits
    // for half the difference.
    const double in_order = 0.5 * ((y.box + y.t2) - (x.box + x.t2));
    if (x.none) return std::max(0.5 * y.box, in_order);  // no step
    if (y.none) return std::max(0.5 * x.box, in_order);
    if (x.t2 != y.t2 || x.own || y.own) return 0.5 * (x.box + x.t2 + y.box + y.t2);
    return 0.5 * (x.box + y.box) + ((x.gapped || y.gapped) && gap(rules, x, y, memo) ? x.t2 : 0.0);
}

}  // namespace

bool SpacingRules::needs_gap(const AxisVector& x, const AxisVector& y, double stage) const {
    double box_x = -1.0, box_y = -1.0;
    return gap_between(*this, stage, x, 1.0, box_x, y, 1.0, box_y);
}

double SpacingRules::unit_box(const AxisVector& d) const { return firtp::unit_box(limits, d); }

double SpacingRules::spacing(const StepShape& x, const StepShape& y) const {
    StepView vx = view(*this, x), vy = view(*this, y);
    return firtp::spacing(*this, vx, vy);
}

ProfileLegs profile_legs(const SpacingRules& rules, const ProfileInput& block, double a, double p, double b) {
    // The steps in order and the speed of the leg after each: in, [a -> p], [p -> b], out.
    // (Views of the shapes, not copies: each step's unit box is found once, when a gap needs it.)
    std::array<StepView, 4> steps;
    std::array<double, 3> speed{};
    std::array<int, 3> leg{};  // which of x0, xp, x1 each gap between steps is
    int n = 0;
    steps[n] = view(rules, block.in, 0);
    // A ramp's box and jerk stage: the block's own, or those of the junction's regime it shares.
    const double own_t2 = block.t2 < 0.0 ? rules.t2 : block.t2;
    auto ramp = [&](double dv, double alpha, double t2, bool gapped) {
        const bool own = t2 < 0.0;
        return StepView{std::abs(dv) * (own ? block.alpha : alpha), own ? own_t2 : t2, &block.u, dv > 0.0 ? 1.0 : -1.0, false,
                        block.u_unit_box, dv > 0.0 ? 1 : 2, false, own || gapped || t2 == rules.t2};
    };
    if (p != a) {
        speed[n] = a, leg[n] = 0;
        steps[++n] = ramp(p - a, block.in_alpha, block.in_t2, block.in_gapped);
    }
    if (b != p) {
        speed[n] = p, leg[n] = n == 0 ? 0 : 1;
        steps[++n] = ramp(b - p, block.out_alpha, block.out_t2, block.out_gapped);
    }
    speed[n] = b, leg[n] = n == 0 ? 0 : 2;
    steps[++n] = view(rules, block.out, 3);
    std::array<double, 3> x{};
    for (int i = 0; i < n; ++i) x[i] = spacing(rules, steps[i], steps[i + 1], block.gaps);
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
    // A ramp sharing a corner's jerk stage in a dense run's regime: its kernel ends by the
    // corner's middle (its lead there would add to the corner's error).
    auto clear_of_corner = [&](const StepView& corner, const StepView& r) {
        return r.t2 == corner.t2 && !corner.gapped && !corner.own && corner.box > 0.0 ? 0.5 * (r.box + r.t2) : 0.0;
    };
    if (n >= 2) {
        x[0] = std::max(x[0], clear_of_corner(steps[0], steps[1]));
        x[n - 1] = std::max(x[n - 1], clear_of_corner(steps[n], steps[n - 1]));
    }
    x[0] = std::max(x[0], block.entry_elapsed + 0.5 * (steps[1].box + steps[1].t2));
    // Steps further apart than neighbours: boxes of opposite sign on an axis keep T2 between them.
    for (int i = 0; i + 2 <= n; ++i)
        for (int k = i + 2; k <= n; ++k) {
            if (steps[i].t2 != steps[k].t2 || !(steps[i].gapped || steps[k].gapped) || steps[i].own || steps[k].own ||
                !gap(rules, steps[i], steps[k], block.gaps))
                continue;
            double apart = 0.0;
            for (int m = i; m < k; ++m) apart += x[m];
            const double need = 0.5 * (steps[i].box + steps[k].box) + steps[i].t2;
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
    legs.margin = extra + 1e-12 * block.length;
    legs.fits = extra >= -1e-12 * block.length;
    if (legs.fits && extra != 0.0) {
        if (speed[fastest] > 0.0) x[fastest] = std::max(0.0, x[fastest] + extra / speed[fastest]);
        else legs.fits = extra <= 0.0;  // nothing moves: the block cannot be covered
    }
    std::array<double, 3> sum{};
    for (int i = 0; i < n; ++i) sum[leg[i]] += x[i];
    legs.x0 = sum[0], legs.xp = sum[1], legs.x1 = sum[2];
    return legs;
}

}  // namespace firtp
