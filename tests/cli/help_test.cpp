// firtp --help and firtp plan --help: exit 0 and name every subcommand and flag.
#include "cli_runner.hpp"

#include <gtest/gtest.h>

namespace firtp::cli_test {
namespace {

TEST(Help, TopLevelListsPlan) {
    const Outcome r = run_firtp({"--help"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("plan"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Usage: firtp"), std::string::npos) << r.out;
}

TEST(Help, PlanDocumentsEveryFlag) {
    const Outcome r = run_firtp({"plan", "--help"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const char* flag : {"--help", "--ini", "--t1", "--t2", "--tolerance", "--period", "--tolerance-meaning",
                             "--csv", "--json", "--plot", "corner|contour", "gnuplot-nox"})
        EXPECT_NE(r.out.find(flag), std::string::npos) << flag << " missing from\n" << r.out;
}

TEST(Help, NoCommandIsAUsageError) {
    const Outcome r = run_firtp({});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("Usage: firtp"), std::string::npos) << r.err;
}

TEST(Help, UnknownCommandIsAUsageError) {
    const Outcome r = run_firtp({"fly"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("firtp: unknown command 'fly'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace firtp::cli_test
