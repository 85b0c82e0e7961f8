// Smoothing at the limits: a block never cruises above its programmed feed at 100 %. A block
// entered faster than its feed (the corner before it was planned for the highest override) used to
// give its spare length to that entry leg and run most of its length there: here 27.7 mm at 2 F
// (max_rate 2), 0.93 s early. A short (dense, one-speed) block planned from rest ran at the next
// block's feed at the highest override into the corner after it, and so did the dense block after
// that corner. Found by firtp_cliffs (seed 31, program 3; seed 7, program 270). Measured on the
// samples: the path speed wherever the tool is in the middle half of a block.
#include <firtp/planner.hpp>
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

using namespace firtp;

namespace {

// The fastest path speed in the middle half of the block from `a` to `b` (program line `line`), and
// how many samples lie there.
std::pair<double, int> middle_half_speed(const Trajectory& t, const AxisVector& a, const AxisVector& b, std::int64_t line) {
    const AxisVector u = (b - a).normalized();
    const double length = (b - a).norm();
    double fastest = 0.0;
    int inside = 0;
    for (const AxisState& s : t.samples) {
        const double x = (s.position - a).dot(u);
        if (s.line != line || x < 0.25 * length || x > 0.75 * length) continue;
        fastest = std::max(fastest, s.velocity.norm());
        ++inside;
    }
    return {fastest, inside};
}

// Three axes as the random machine drew them, 64 blocks of look-ahead, overrides up to 200 %.
PlannerParameters machine(const AxisLimits& x, const AxisLimits& y, const AxisLimits& z, double period) {
    PlannerParameters p;
    p.limits.axes = 3;
    p.limits.axis[0] = x;
    p.limits.axis[1] = y;
    p.limits.axis[2] = z;
    p.period = period;
    p.max_rate = 2.0;
    p.queue_capacity = 64;
    return p;
}

TEST(ProgrammedFeed, ABlockEnteredAboveItsFeedLeavesThatSpeedAtOnce) {
    const PlannerParameters p = machine({286.23985289444931, 304.85719042601966, 10623999.538938846},
                                        {56.365272543570043, 25614.037821193127, 1345104.9702734549},
                                        {171.60329139979541, 14037.079562977451, 2277922.9016302587}, 0.0005);
    AxisVector a = AxisVector::Zero(), b = AxisVector::Zero();
    a.head<3>() << -4.1237721515922745, -3.9800643782236498, -0.045310815526213431;
    b.head<3>() << -21.455956711423372, -10.700448772635918, -20.629284722515639;
    const double slow = 14.175480427980693;
    const std::vector<Block> blocks{{a, 516.3714776874325, Termination::blend, 0.12661372788970729, MotionType::feed, 1},
                                    {b, slow, Termination::blend, 0.0016146422007566141, MotionType::feed, 2}};
    const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
    const auto [fastest, inside] = middle_half_speed(t, a, b, 2);
    EXPECT_GT(inside, 100);
    EXPECT_LE(fastest, slow * (1.0 + 1e-6)) << "the middle half of the block above its feed";
    EXPECT_GE(t.cycle_time, (b - a).norm() / slow);  // not a result: the floor the feed itself sets
    EXPECT_LT((t.samples.back().position - b).norm(), 1e-9);
}

TEST(ProgrammedFeed, ADenseBlockKeepsTheFeedOfTheBlockAfterItsCorner) {
    const PlannerParameters p = machine({468.34483512449827, 7959.4527756540629, 47109572.165463202},
                                        {151.8778363053593, 23040.089333729658, 34296.085251330551},
                                        {308.13185955903521, 344.41361937022373, 12508.198989193546}, 0.001);
    AxisVector a = AxisVector::Zero(), b = AxisVector::Zero(), c = AxisVector::Zero(), d = AxisVector::Zero();
    a.head<3>() << 9.3762987794749275, -1.4567346845453317, 3.2954188402868305;
    b.head<3>() << 11.200311815263831, -1.8022997165620811, 3.8660332708798566;
    c.head<3>() << 47.315858717714633, -8.6445041727654264, 15.164226774406275;
    d.head<3>() << 71.491186034076051, -13.745489250662928, 23.073219007177194;
    const double fast = 399.07093024365076, slow = 9.6072306583789846;
    const std::vector<Block> blocks{{a, fast, Termination::blend, 0.1514532662495065, MotionType::feed, 1},
                                    {b, slow, Termination::blend, 0.1514532662495065, MotionType::feed, 2},
                                    {c, 18.40106340844973, Termination::blend, 0.023295409389648431, MotionType::feed, 3},
                                    {d, fast, Termination::blend, 0.1514532662495065, MotionType::feed, 4}};
    const Trajectory t = plan_trajectory(p, AxisVector::Zero(), blocks);
    const auto [fastest, inside] = middle_half_speed(t, a, b, 2);  // 1.9 mm, dense at 2 F before
    EXPECT_GT(inside, 20);
    EXPECT_LE(fastest, slow * (1.0 + 1e-6)) << "the middle half of the block above its feed";
    EXPECT_LT((t.samples.back().position - d).norm(), 1e-9);
}

// Blocks added one at a time, a period between each (as firtp_tp and firtp.so take them): the
// block before the newest was planned with the stop at the end of the path after it, and kept
// that plan when the newest made its end a corner, where its bounds did not change: it left the
// corner at its own feed (81.06 mm/s), above the next block's 56.02, which the next block then
// braked from (random seed 1 program 43; plan_trajectory, planning the two at once, did not).
TEST(ProgrammedFeed, TheBlockBeforeTheNewestIsPlannedAgainForItsCorner) {
    PlannerParameters p;
    p.limits.axes = 2;
    p.limits.axis[0] = {80.934583018461694, 7300.2501078571713, 1321903.7854885906};
    p.limits.axis[1] = {253.99391015781211, 1244.6945948199213, 70275596.866552189};
    p.period = 0.0005;
    p.max_rate = 2.0;
    p.queue_capacity = 64;
    AxisVector a = AxisVector::Zero(), b = AxisVector::Zero();
    a.head<2>() << -54.05575420844427, 3.0115427295889918;
    b.head<2>() << -92.45110612383499, 5.4070301371953544;
    const double slow = 56.021738729489485, tolerance = 0.0011622480766995803;
    const std::vector<Block> blocks{{a, 572.28277167974045, Termination::blend, tolerance, MotionType::feed, 1},
                                    {b, slow, Termination::blend, tolerance, MotionType::feed, 2}};
    for (const Planning when : {Planning::now, Planning::at_update}) {
        Planner planner(p, AxisVector::Zero());
        PlannerInput in;
        PlannerOutput out;
        std::vector<AxisState> samples;
        for (const Block& block : blocks) {
            ASSERT_EQ(planner.add(block, when), Result::ok);
            planner.update(in, out);
            samples.push_back(out.state);
        }
        in.end_of_program = true;
        for (Result r = Result::working; r == Result::working;) {
            r = planner.update(in, out);
            samples.push_back(out.state);
        }
        // Past the corner (along the path) the tool is in the slow block: at most its feed.
        const AxisVector u = (b - a).normalized();
        double fastest = 0.0;
        for (const AxisState& s : samples)
            if ((s.position - a).dot(u) > 0.0) fastest = std::max(fastest, s.velocity.norm());
        EXPECT_LE(fastest, slow * (1.0 + 1e-6)) << (when == Planning::now ? "added now" : "added at the update");
        EXPECT_LT((samples.back().position - b).norm(), 1e-9);
    }
}

}  // namespace
