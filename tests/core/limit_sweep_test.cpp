// LimitSweep (motion_check.hpp) on legs taken from a plan it once refused wrongly (random machine,
// seed 32, program 878 of RandomMachines.HoldResumeRegressions): a junction step of almost no
// speed change has a second stage of 8.4e-18 s, whose jerks of 1e21 cancelled between the two
// legs with rounding errors of 1e5; the sweep then saw 549.5 mm/s^2 on X where the motion has 420.6.
#include <firtp/motion_check.hpp>

#include <gtest/gtest.h>

#include <array>
#include <vector>

using namespace firtp;

namespace {

// rise, fall, tv, rising a, b, falling a, b, delta X Y Z A
constexpr std::array<std::array<double, 11>, 6> plan_878 = {{
    {0, 0.1754521310619902, 0.16157015188447002, 0.037568555187117651, 0.0010481483012585518, 0.0098045968320772652,
     0.0010481483012585518, 2.5529318390031484, -0.70492174968604948, 0.36549409107360037, 0.87434101311548651},
    {0.1754521310619902, 0.010852745133335839, 0.005950446717297192, 0.0098045968320772652, 0.0010481483012585518,
     0.0010481483012585518, 8.4470801491154888e-18, 0.069483957851886269, -0.019186079469786808, 0.0099477689264073649,
     0.023797217448317892},
    {0.18630487619532604, 0.0010481483012461101, 0.011121411152680394, 0.0010481483012585518, 8.4470801491154888e-18,
     0.020146525702868557, 0.0010481483012585518, 0.12986582360951635, -0.035858867128621102, 0.01859242398740207,
     0.044477104342965201},
    {0.18735302449657215, 0.020599837901472101, 0.010597337002063556, 0.020146525702868557, 0.0010481483012585518,
     0.0010481483012585518, 0.00014152390405144599, 0.033951499632882659, -0.0093747706695617022, 0.0048607143791788493,
     0.011627881376337813},
    {0.20795286239804425, 0.0011896722053100217, 0.0014704587663783575, 0.0010481483012585518, 0.00014152390405144599,
     0.0010481483012585518, 0.00070309702618814667, 0.0046234954617703572, -0.0015080834774504437, 0.00079025531737356614,
     0.0016335399358780762},
    {0.20914253460335427, 0.001751245327440254, 0.0054891997015004412, 0.0010481483012585518, 0.00070309702618814667,
     0.008179005774308537, 0.0010481483012585518, 0.018882658508581965, -0.0061591117678371559, 0.003227454512703763,
     0.0066714841669825451},
}};

std::vector<TimedLeg> legs_878() {
    std::vector<TimedLeg> legs;
    for (const auto& r : plan_878) {
        TimedLeg l;
        l.rise = r[0], l.fall = r[1], l.tv = r[2];
        l.rising = Kernel{r[3], r[4]};
        l.falling = Kernel{r[5], r[6]};
        for (int i = 0; i < 4; ++i) l.delta[i] = r[7 + i];
        legs.push_back(l);
    }
    index_legs(legs);
    return legs;
}

MachineLimits machine_878(double x_acceleration) {
    MachineLimits m;
    m.axes = 4;
    m.axis[0] = {83.0991, x_acceleration, 623557};
    m.axis[1] = {169.225, 17708, 7.63293e+07};
    m.axis[2] = {147.893, 3341.11, 3.18763e+06};
    m.axis[3] = {367.104, 2105.15, 2.40115e+06};
    return m;
}

// The largest |X acceleration| of the legs' sum, sampled every microsecond.
double sampled_x_acceleration(const std::vector<TimedLeg>& legs) {
    double most = 0.0;
    for (double t = 0.0; t <= 0.22; t += 1e-6) most = std::max(most, std::abs(relative_state(legs, 0, t).acceleration[0]));
    return most;
}

}  // namespace

TEST(LimitSweep, ANegligibleSecondStageIsCheckedAsOne) {
    const std::vector<TimedLeg> legs = legs_878();
    const double x = sampled_x_acceleration(legs);
    EXPECT_NEAR(x, 420.58, 0.01);  // the motion: X at its limit of 420.585 during the ramp
    LimitSweep sweep(64);
    EXPECT_TRUE(sweep.check(legs, 0.0, 0.22, machine_878(420.585), 0.00025).ok);
    const LimitCheck lowered = sweep.check(legs, 0.0, 0.22, machine_878(0.999 * x), 0.00025);
    EXPECT_FALSE(lowered.ok);  // and not blind: 0.1 % below it, the ramp is over
    EXPECT_EQ(lowered.axis, 0);
    EXPECT_EQ(lowered.derivative, 2);
    EXPECT_NEAR(std::abs(lowered.value), x, 0.01);
}
