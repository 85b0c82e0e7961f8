// The newest block, classed dense after a sparse block by the estimates, ends at the window's
// stop: its class is planned both ways there, and sparse is kept where that plan is faster
// (lookahead_stop.cpp, class_if_faster). The next block decides its class again as the estimates
// left it (link()). Measured on the samples: cycle time, limits (also as 1 ms differences), corner
// errors and the end point (as_drawn_and_raised).
#include "support/raised.hpp"
#include "support/random_machine.hpp"

#include <firtp/trajectory.hpp>

#include <gtest/gtest.h>

#include <array>
#include <vector>

using namespace firtp;

// firtp_cliffs seed 7 program 108: 2.36 mm, then a last block of 0.36 mm at 51.6 degrees. As drawn
// the corner stops and the last block ramps to 9.7 mm/s: 0.2305 s. With every tolerance a quarter
// larger the estimates classed the last block dense; it crawled from the corner at 4.8 mm/s to its
// stop: 0.250 s. Planned both ways, it stays sparse: 0.2305 s both.
TEST(NewestClass, ALastBlockThatCrawlsDenseIsPlannedSparse) {
    const std::vector<Block> blocks = test::drawn_blocks(
        {{-1.8809470675272908, -1.4034170091019609, -0.2202697398837829}, {-2.1300354104401551, -1.4873574022406164, 0.029992347734266289}},
        {26.6558, 26.6558}, {0.0105666, 0.00223137});
    const PlannerParameters p = test::drawn_machine(0.0005, 2.0, {{67.8383, 13569.7, 19062.1}, {142.708, 20590.4, 31803.2}, {82.3188, 1925.86, 25254.1}});
    const std::array<Trajectory, 2> t = test::as_drawn_and_raised(p, blocks);
    test::expect_no_cliff(t, p);
    EXPECT_LT(t[1].cycle_time, 0.24);
}

// firtp_cliffs seed 5 program 295: a run of 1.15 mm chords after a G61 block. As the newest, the
// 10th block was planned faster sparse, and its corner stopped. When the next block came, that
// stop (one that pays, classify) kept it sparse, and the dense run after it started from rest:
// 1.169 s instead of 1.086 s. Decided again as the estimates left it: 1.086 s.
TEST(NewestClass, TheNextBlockDecidesItsClassAgain) {
    std::vector<Block> blocks = test::drawn_blocks(
        {{-0.74544260852148103, -0.01479997950221062, 1.5105606375139695, -0.17755292451528096, 0.34075947685411567},
         {-2.7497998410654452, -0.054594385694788021, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-3.8950747300366846, 0.063540777684504945, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-4.977385971660496, 0.45624023578122586, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-5.9319472894436078, 1.0999973163068733, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-6.7016194141210192, 1.9562772405310103, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-7.2403303941497512, 2.9738237840027182, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-7.5158334255053489, 4.0917274327348494, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-7.5116371193176796, 5.2430713775007538, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-7.2279926630848177, 6.3589370999705768, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-6.6818787847923637, 7.3725297795372313, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-5.9059854199738222, 8.2231765773124863, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-4.9467569185806992, 8.8599584632434887, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-3.861611923718141, 9.2447581881127761, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-2.7155063380588218, 9.3545419512804191, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-1.5770451159886978, 9.1827381853806571, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {-0.51437562646537716, 8.7396309250350548, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106},
         {0.40889159342946702, 8.0517442128488224, 5.5721786673748133, -0.65495988293611929, 1.2569986536636106}},
        std::vector<double>(18, 111.926),
        {0.00148714, 0.101379, 0.101379, 0.0345602, 0.101379, 0.101379, 0.101379, 0.0160208, 0.101379, 0.101379, 0.101379,
         0.101379, 0.101379, 0.101379, 0.101379, 0.0736255, 0.101379, 0.116132});
    blocks[3].termination = Termination::exact_stop;
    for (std::size_t k : {4u, 10u, 12u, 17u}) blocks[k].type = MotionType::traverse;
    const PlannerParameters p = test::drawn_machine(0.00025, 1.2, {{158.984, 1811.95, 21095.1}, {302.571, 10937.4, 26401.2},
                                                                {127.217, 1348.33, 1.17697e+06}, {442.39, 7037.76, 112684.0},
                                                                {474.845, 929.659, 4.31702e+07}});
    const std::array<Trajectory, 2> t = test::as_drawn_and_raised(p, blocks);
    test::expect_no_cliff(t, p);
    EXPECT_LT(t[0].cycle_time, 1.1);
}
