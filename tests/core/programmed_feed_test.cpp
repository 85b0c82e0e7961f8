// Smoothing at the limits: a block never cruises above its programmed feed at 100 %. A block
// entered faster than its feed (the corner before it was planned for the highest override) used to
// give its spare length to that entry leg and run most of its length there: here 27.7 mm at 2 F
// (max_rate 2), 0.93 s early. Found by firtp_cliffs (seed 31, program 3). Measured on the samples:
// the path speed wherever the tool is in the middle half of the block.
#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

using namespace firtp;

namespace {

TEST(ProgrammedFeed, ABlockEnteredAboveItsFeedLeavesThatSpeedAtOnce) {
    PlannerParameters p;
    p.limits.axes = 3;
    p.limits.axis[0] = {286.23985289444931, 304.85719042601966, 10623999.538938846};
    p.limits.axis[1] = {56.365272543570043, 25614.037821193127, 1345104.9702734549};
    p.limits.axis[2] = {171.60329139979541, 14037.079562977451, 2277922.9016302587};
    p.period = 0.0005;
    p.max_rate = 2.0;
    p.queue_capacity = 64;
    const AxisVector start = AxisVector::Zero();
    AxisVector a = AxisVector::Zero(), b = AxisVector::Zero();
    a.head<3>() << -4.1237721515922745, -3.9800643782236498, -0.045310815526213431;
    b.head<3>() << -21.455956711423372, -10.700448772635918, -20.629284722515639;
    const double slow = 14.175480427980693;
    const std::vector<Block> blocks{{a, 516.3714776874325, Termination::blend, 0.12661372788970729, MotionType::feed, 1},
                                    {b, slow, Termination::blend, 0.0016146422007566141, MotionType::feed, 2}};
    const Trajectory t = plan_trajectory(p, start, blocks);

    const AxisVector u = (b - a).normalized();
    const double length = (b - a).norm();
    double fastest = 0.0;
    int inside = 0;
    for (const AxisState& s : t.samples) {
        const double x = (s.position - a).dot(u);
        if (s.line != 2 || x < 0.25 * length || x > 0.75 * length) continue;
        fastest = std::max(fastest, s.velocity.norm());
        ++inside;
    }
    EXPECT_GT(inside, 100);
    EXPECT_LE(fastest, slow * (1.0 + 1e-6)) << "the middle half of the block above its feed";
    EXPECT_GE(t.cycle_time, length / slow);  // not a result: the floor the feed itself sets
    EXPECT_LT((t.samples.back().position - b).norm(), 1e-9);
}

}  // namespace
