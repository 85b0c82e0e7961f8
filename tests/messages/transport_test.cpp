// open(), default_url(), keep_everything(), and publish/handle on memq://.
#include "sample.hpp"

#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace firtp::messages {
namespace {

std::string open_error(const std::string& url) {
    try {
        open(url);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(opened)";
}

using test::contains;

// Sets an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        ::setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (old_) ::setenv(name_, old_->c_str(), 1);
        else ::unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

struct BlockSink {
    std::vector<firtp_lcm::block_t> received;
    void on_block(const lcm::ReceiveBuffer*, const std::string&, const firtp_lcm::block_t* message) {
        received.push_back(*message);
    }
};

struct StatusSink {
    std::vector<firtp_lcm::status_t> received;
    void on_status(const lcm::ReceiveBuffer*, const std::string&, const firtp_lcm::status_t* message) {
        received.push_back(*message);
    }
};

void drain(lcm::LCM& lcm) {
    while (lcm.handleTimeout(0) > 0) {
    }
}

TEST(Transport, DefaultUrlIsLocalMulticastWithBigBuffer) {
    EXPECT_EQ(default_url(), "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608");
}

TEST(Transport, OpensMemq) {
    auto lcm = open("memq://");
    ASSERT_NE(lcm, nullptr);
    EXPECT_TRUE(lcm->good());
}

TEST(Transport, FailureNamesUrlAndHint) {
    const std::string error = open_error("nosuch://here");
    EXPECT_TRUE(contains(error, "'nosuch://here'")) << error;
    EXPECT_TRUE(contains(error, "unknown provider")) << error;

    const std::string missing = open_error("file:///nonexistent/firtp/none.lcmlog");
    EXPECT_TRUE(contains(missing, "file:///nonexistent/firtp/none.lcmlog")) << missing;
}

// An address LCM cannot use fails on any host, so the error shows the URL that was really tried.
TEST(Transport, UdpmGetsAReceiveBuffer) {
    std::string error = open_error("udpm://300.1.1.1:7667");
    EXPECT_TRUE(contains(error, "'udpm://300.1.1.1:7667?recv_buf_size=8388608'")) << error;
    EXPECT_TRUE(contains(error, "multicast route")) << error;

    error = open_error("udpm://300.1.1.1:7667?ttl=0");
    EXPECT_TRUE(contains(error, "'udpm://300.1.1.1:7667?ttl=0&recv_buf_size=8388608'")) << error;

    error = open_error("udpm://300.1.1.1:7667?recv_buf_size=1000");
    EXPECT_TRUE(contains(error, "'udpm://300.1.1.1:7667?recv_buf_size=1000'")) << error;
}

TEST(Transport, EmptyUrlFollowsLcmDefaultUrl) {
    {
        const ScopedEnv env("LCM_DEFAULT_URL", "memq://");
        EXPECT_TRUE(open("")->good());
    }
    const ScopedEnv env("LCM_DEFAULT_URL", "nosuch://from-env");
    EXPECT_TRUE(contains(open_error(""), "'nosuch://from-env'"));
}

TEST(Transport, KeepEverythingNeedsASubscription) {
    EXPECT_THROW(keep_everything(nullptr), std::invalid_argument);
}

TEST(Transport, BurstOfTenThousandBlocksArrivesComplete) {
    constexpr std::int64_t count = 10'000;
    auto lcm = open("memq://");
    BlockSink sink;
    keep_everything(lcm->subscribe(block_channel, &BlockSink::on_block, &sink));
    for (std::int64_t seq = 1; seq <= count; ++seq) {
        const auto message = test::sample_message(seq);
        ASSERT_EQ(lcm->publish(block_channel, &message), 0);
    }
    drain(*lcm);
    ASSERT_EQ(static_cast<std::int64_t>(sink.received.size()), count);
    for (std::int64_t i = 0; i < count; ++i) {
        ASSERT_EQ(sink.received[static_cast<std::size_t>(i)].seq, i + 1);
        ASSERT_EQ(validate(sink.received[static_cast<std::size_t>(i)]), std::nullopt);
    }
}

TEST(Transport, ChannelsKeepTheirTypesApart) {
    auto lcm = open("memq://");
    BlockSink blocks;
    StatusSink statuses;
    keep_everything(lcm->subscribe(block_channel, &BlockSink::on_block, &blocks));
    keep_everything(lcm->subscribe(status_channel, &StatusSink::on_status, &statuses));

    firtp_lcm::status_t status{};
    status.seq = 1;
    status.next_seq = 2;
    status.state = firtp_lcm::status_t::MOVING;
    status.error_text = "";
    const auto block = test::sample_message(1);
    lcm->publish(status_channel, &status);
    lcm->publish(block_channel, &block);
    drain(*lcm);
    ASSERT_EQ(blocks.received.size(), 1U);
    ASSERT_EQ(statuses.received.size(), 1U);
    EXPECT_EQ(statuses.received[0].next_seq, 2);
    EXPECT_EQ(statuses.received[0].state, firtp_lcm::status_t::MOVING);
}

}  // namespace
}  // namespace firtp::messages
