#include <firtp/ini.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

using firtp::ConfigError;
using firtp::IniFile;

std::string parse_error(std::string_view text) {
    try {
        IniFile::parse(text, "m.ini");
    } catch (const ConfigError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Ini, ReadsSectionsKeysAndSkipsComments) {
    const IniFile ini = IniFile::parse("# machine\n"
                                       "\n"
                                       "[EMCMOT]\n"
                                       "  SERVO_PERIOD =  1000000  \n"
                                       "; a comment\n"
                                       "[AXIS_X]\n"
                                       "MAX_VELOCITY=50\n"
                                       "HOME_SEQUENCE = \n"
                                       "MIN_LIMIT = -1 = odd\n",
                                       "m.ini");
    EXPECT_EQ(ini.file_name(), "m.ini");
    const IniFile::Entry* e = ini.find("EMCMOT", "SERVO_PERIOD");
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->value, "1000000");
    EXPECT_EQ(e->line, 4);
    EXPECT_EQ(ini.find("AXIS_X", "MAX_VELOCITY")->value, "50");
    EXPECT_EQ(ini.find("AXIS_X", "HOME_SEQUENCE")->value, "");
    EXPECT_EQ(ini.find("AXIS_X", "MIN_LIMIT")->value, "-1 = odd");  // split at the first '='
    EXPECT_EQ(ini.find("AXIS_X", "SERVO_PERIOD"), nullptr);
    EXPECT_EQ(ini.find("AXIS_Y", "MAX_VELOCITY"), nullptr);
    EXPECT_EQ(ini.section("AXIS_X").size(), 3u);
    EXPECT_TRUE(ini.section("TRAJ").empty());
}

TEST(Ini, FirstRepeatedKeyWins) {
    const IniFile ini = IniFile::parse("[A]\nK = 1\nK = 2\n[B]\nK = 3\n[A]\nK = 4\n", "m.ini");
    EXPECT_EQ(ini.find("A", "K")->value, "1");
    EXPECT_EQ(ini.find("A", "K")->line, 2);
    EXPECT_EQ(ini.find("B", "K")->value, "3");
    EXPECT_EQ(ini.section("A").size(), 3u);
}

TEST(Ini, HandlesCrLfAndNoFinalNewline) {
    const IniFile ini = IniFile::parse("[A]\r\nK = 1\r\nL = 2", "m.ini");
    EXPECT_EQ(ini.find("A", "K")->value, "1");
    EXPECT_EQ(ini.find("A", "L")->value, "2");
    EXPECT_EQ(ini.find("A", "L")->line, 3);
}

TEST(Ini, SyntaxErrorsNameFileAndLine) {
    EXPECT_EQ(parse_error("# c\nK = 1\n"), "m.ini:2: KEY = VALUE before any [SECTION]");
    EXPECT_EQ(parse_error("[A]\nK = 1\n\nJUST TEXT\n"), "m.ini:4: expected KEY = VALUE, a [SECTION] or a comment");
    EXPECT_EQ(parse_error("[A\n"), "m.ini:1: section header is missing ']'");
    EXPECT_EQ(parse_error("[]\n"), "m.ini:1: empty section name '[]'");
    EXPECT_EQ(parse_error("[A] x\n"), "m.ini:1: unexpected text after the section header");
    EXPECT_EQ(parse_error("[A]\n = 3\n"), "m.ini:2: missing key before '='");
}

TEST(Ini, NumberAcceptsFiniteDecimals) {
    const IniFile ini = IniFile::parse("[A]\nI = 12\nD = -0.5\nP = +3\nE = 1e3\n", "m.ini");
    EXPECT_EQ(ini.number("A", "I"), 12.0);
    EXPECT_EQ(ini.number("A", "D"), -0.5);
    EXPECT_EQ(ini.number("A", "P"), 3.0);
    EXPECT_EQ(ini.number("A", "E"), 1000.0);
    EXPECT_EQ(ini.number("A", "MISSING"), std::nullopt);
}

TEST(Ini, NumberRejectsTextNanAndInfinity) {
    const IniFile ini =
        IniFile::parse("[A]\nT = fast\nN = nan\nI = inf\nX = 12 # mm\nE =\nS = +-1\n", "m.ini");
    const auto error = [&](const char* key) {
        try {
            ini.number("A", key);
        } catch (const ConfigError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("T"), "m.ini:2: [A]T: 'fast' is not a number");
    EXPECT_EQ(error("N"), "m.ini:3: [A]N: 'nan' is not a number");
    EXPECT_EQ(error("I"), "m.ini:4: [A]I: 'inf' is not a number");
    EXPECT_EQ(error("X"), "m.ini:5: [A]X: '12 # mm' is not a number");  // no inline comments
    EXPECT_EQ(error("E"), "m.ini:6: [A]E: '' is not a number");
    EXPECT_EQ(error("S"), "m.ini:7: [A]S: '+-1' is not a number");
}

TEST(Ini, ReadReportsMissingFile) {
    try {
        IniFile::read("/nonexistent/firtp.ini");
        FAIL() << "no error";
    } catch (const ConfigError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/firtp.ini:0: cannot open file");
    }
}

}  // namespace
