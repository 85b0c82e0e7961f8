// firtp/defaults.hpp: each default's number is read from the text the help texts and man pages
// show; the tolerance meaning's words parse and print as the INI, the CLI and the modules spell them.
#include <firtp/defaults.hpp>
#include <firtp/parameters.hpp>

#include <gtest/gtest.h>

#include <string>

namespace firtp {
namespace {

TEST(Defaults, TextsReadAsTheNearestDouble) {
    EXPECT_EQ(decimal_value("0.05"), 0.05);
    EXPECT_EQ(decimal_value("0.2"), 0.2);
    EXPECT_EQ(decimal_value("0.001"), 0.001);
    EXPECT_EQ(decimal_value("1"), 1.0);
    EXPECT_EQ(decimal_value("12.345"), 12.345);
    EXPECT_EQ(decimal_value("0.1"), 0.1);
    EXPECT_EQ(defaults::servo_period, 0.001);
}

TEST(Defaults, PlannerParametersStartFromThem) {
    const PlannerParameters p;
    EXPECT_EQ(p.period, defaults::servo_period);
    EXPECT_EQ(p.rate_reserve, defaults::rate_reserve);
    EXPECT_EQ(p.max_rate, defaults::max_feed_override);
    EXPECT_EQ(p.tolerance_meaning, ToleranceMeaning::corner_point);
}

TEST(ToleranceMeaningWords, ParseAndPrint) {
    for (const ToleranceMeaning m : {ToleranceMeaning::corner_point, ToleranceMeaning::contour})
        EXPECT_EQ(parse_tolerance_meaning(to_string(m)), m);
    EXPECT_EQ(std::string(to_string(ToleranceMeaning::corner_point)), "corner");
    EXPECT_EQ(std::string(to_string(ToleranceMeaning::contour)), "contour");
    EXPECT_FALSE(parse_tolerance_meaning("Contour"));  // the INI reader lowers its value first
    EXPECT_FALSE(parse_tolerance_meaning("corner point"));
    EXPECT_FALSE(parse_tolerance_meaning(""));
}

}  // namespace
}  // namespace firtp
