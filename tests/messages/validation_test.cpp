// validate(): every field a block message can get wrong, and the wording of the answer.
#include "sample.hpp"

#include <cmath>
#include <limits>

namespace firtp::messages {
namespace {

using test::sample_message;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

std::string problem(const firtp_lcm::block_t& message) {
    const auto error = validate(message);
    return error ? *error : std::string("(valid)");
}

TEST(Validate, SampleIsValid) { EXPECT_EQ(validate(sample_message()), std::nullopt); }

TEST(Validate, NamesSeqAndLine) {
    auto message = sample_message(12);
    message.feed = nan;
    EXPECT_EQ(problem(message), "block seq 12 (line 40): feed is NaN (must be finite and > 0)");
}

TEST(Validate, NonFiniteTargetInEachAxis) {
    for (int axis = 0; axis < max_axes; ++axis) {
        for (double bad : {nan, inf, -inf}) {
            auto message = sample_message();
            message.target[axis] = bad;
            const std::string name = std::string("target ") + axis_letters[static_cast<std::size_t>(axis)] + " is ";
            EXPECT_NE(problem(message).find(name), std::string::npos) << problem(message);
        }
    }
    auto message = sample_message();
    message.target[4] = nan;
    EXPECT_EQ(problem(message), "block seq 12 (line 40): target B is NaN");
}

TEST(Validate, TargetWithinOneMillion) {
    auto message = sample_message();
    message.target[0] = 1e6;
    message.target[8] = -1e6;
    EXPECT_EQ(validate(message), std::nullopt);
    message.target[2] = -1000001.0;
    EXPECT_NE(problem(message).find("target Z is -1000001, beyond +-1e6"), std::string::npos) << problem(message);
}

TEST(Validate, FeedMustBePositiveAndFinite) {
    for (double bad : {0.0, -0.0, -1.0, nan, inf, -inf}) {
        auto message = sample_message();
        message.feed = bad;
        EXPECT_NE(problem(message).find("feed is "), std::string::npos) << bad;
    }
    auto message = sample_message();
    message.feed = 1e-9;
    EXPECT_EQ(validate(message), std::nullopt);
}

TEST(Validate, ToleranceMustBePositiveOrInfinite) {
    for (double bad : {0.0, -0.0, -0.01, nan, -inf}) {
        auto message = sample_message();
        message.tolerance = bad;
        EXPECT_NE(problem(message).find("tolerance is "), std::string::npos) << bad;
    }
    for (auto termination : {Termination::exact_stop, Termination::blend}) {
        auto message = sample_message();
        message.termination = static_cast<std::int8_t>(termination);
        message.tolerance = 0.0;
        EXPECT_EQ(problem(message), "block seq 12 (line 40): tolerance is 0 (must be > 0 or inf)");
        message.tolerance = inf;
        EXPECT_EQ(validate(message), std::nullopt);
    }
}

TEST(Validate, UnknownMotionType) {
    for (int bad : {0, 3, -1, 127}) {
        auto message = sample_message();
        message.motion_type = static_cast<std::int8_t>(bad);
        EXPECT_EQ(problem(message), "block seq 12 (line 40): unknown motion_type " + std::to_string(bad) +
                                        " (1 traverse, 2 feed)");
    }
    auto message = sample_message();
    message.motion_type = 1;
    EXPECT_EQ(validate(message), std::nullopt);
}

TEST(Validate, UnknownTermination) {
    for (int bad : {2, -1, 64}) {
        auto message = sample_message();
        message.termination = static_cast<std::int8_t>(bad);
        EXPECT_EQ(problem(message), "block seq 12 (line 40): unknown termination " + std::to_string(bad) +
                                        " (0 exact stop, 1 blend)");
    }
}

TEST(Validate, SeqStartsAtOne) {
    EXPECT_EQ(problem(sample_message(0)), "block seq 0 (line 40): seq must be >= 1");
    EXPECT_EQ(problem(sample_message(-3)), "block seq -3 (line 40): seq must be >= 1");
    EXPECT_EQ(validate(sample_message(1)), std::nullopt);
}

TEST(Validate, ListsEveryProblem) {
    auto message = sample_message(5);
    message.target[1] = inf;
    message.feed = -2.0;
    message.tolerance = nan;
    EXPECT_EQ(problem(message), "block seq 5 (line 40): target Y is inf; feed is -2 (must be finite and > 0); "
                                "tolerance is NaN (must be > 0 or inf)");
}

}  // namespace
}  // namespace firtp::messages
