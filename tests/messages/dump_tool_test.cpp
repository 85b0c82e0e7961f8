// firtp-lcm-dump on a small log written here: event lines, --channel, --count with gaps.
#include "sample.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <sys/wait.h>
#include <vector>

namespace firtp::messages {
namespace {

struct ToolRun {
    int code = -1;
    std::string out;  // stdout and stderr
};

ToolRun dump(const std::string& arguments) {
    const std::string command = std::string(FIRTP_LCM_DUMP) + " " + arguments + " 2>&1";
    ToolRun run;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return run;
    std::array<char, 4096> buffer{};
    while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) run.out.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

void write_bytes(lcm::LogFile& log, const std::string& channel, std::int64_t timestamp,
                 std::vector<unsigned char>& bytes) {
    lcm::LogEvent event{};
    event.timestamp = timestamp;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    log.writeEvent(&event);
}

// Sealed, as every sender writes them.
template <class Message> void write(lcm::LogFile& log, const std::string& channel, std::int64_t timestamp,
                                    Message message) {
    std::vector<unsigned char> bytes = seal_encoded(message);
    write_bytes(log, channel, timestamp, bytes);
}

using test::contains;

// Blocks 1 2 4 5 (3 lost), 5 again, then 3 late; a second program; status 1 2; axis states 1 2 5;
// one control; one event of a foreign type.
class DumpTool : public ::testing::Test {
protected:
    void SetUp() override {
        lcm::LogFile log(file_.string(), "w");
        ASSERT_TRUE(log.good());
        std::int64_t time = 1000;
        for (std::int64_t seq : {1, 2, 4, 5, 5, 3}) write(log, block_channel, time++, test::sample_message(seq));
        Block block = test::sample_block();
        block.line = 3;
        write(log, block_channel, time++, to_message(block, 8, 1, 0));

        firtp_lcm::status_t status{};
        status.seq = 1;
        status.program = 7;
        status.next_seq = 3;
        status.state = firtp_lcm::status_t::MOVING;
        status.queue_depth = 2;
        status.queue_free = 62;
        write(log, status_channel, time++, status);
        status.seq = 2;
        status.state = firtp_lcm::status_t::ERROR;
        status.error_code = firtp_lcm::status_t::ERROR_SEQUENCE_GAP;
        status.error_text = "gap at 3";
        write(log, status_channel, time++, status);

        firtp_lcm::axis_state_t axis{};
        axis.line = 40;
        axis.position[0] = 1.5;
        axis.position[1] = -2.0;
        axis.position[2] = 0.125;
        axis.program = 7;
        axis.next_seq = 6;
        for (std::int64_t seq : {1, 2, 5}) {
            axis.seq = seq;
            axis.tick = 100 + seq;
            write(log, axis_state_live_channel, time++, axis);
        }
        firtp_lcm::control_t control{};
        control.seq = 1;
        control.feed_scale = 0.75;
        control.hold = true;
        write(log, control_channel, time++, control);

        lcm::LogEvent foreign{};
        unsigned char bytes[3] = {1, 2, 3};
        foreign.timestamp = time++;
        foreign.channel = "OTHER";
        foreign.datalen = 3;
        foreign.data = bytes;
        log.writeEvent(&foreign);
    }
    test::TempFile file_{".lcmlog"};
};

TEST_F(DumpTool, OneLinePerEvent) {
    const ToolRun run = dump(file_.string());
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_TRUE(contains(run.out, "1000 FIRTP_BLOCK block_t seq=1 program=7 line=40 target=(-2.5,-1,0.5) feed=25 "
                                  "tolerance=0.02\n")) << run.out;
    EXPECT_TRUE(contains(run.out, " FIRTP_STATUS status_t seq=1 program=7 next_seq=3 state=moving queue=2 free=62 error=0\n"))
        << run.out;
    EXPECT_TRUE(contains(run.out, " FIRTP_STATUS status_t seq=2 program=7 next_seq=3 state=error queue=2 free=62 error=2 "
                                  "\"gap at 3\"\n")) << run.out;
    EXPECT_TRUE(contains(run.out, " FIRTP_AXIS_STATE_LIVE axis_state_t seq=5 tick=105 line=40 "
                                  "position=(1.5,-2,0.125) program=7 next_seq=6\n")) << run.out;
    EXPECT_TRUE(contains(run.out, " FIRTP_CONTROL control_t seq=1 feed_scale=0.75 hold=1 abort=0\n")) << run.out;
    EXPECT_TRUE(contains(run.out, "1013 OTHER ? 3 bytes\n")) << run.out;
    EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 14) << run.out;
}

// A status event whose string length is 0 (lcm-gen's decode would throw on it): one "?" line,
// and the tool goes on with the next event.
TEST(DumpToolErrors, CorruptStatusIsShownNotFatal) {
    test::TempFile file{".lcmlog"};
    {
        lcm::LogFile log(file.string(), "w");
        ASSERT_TRUE(log.good());
        firtp_lcm::status_t status{};
        status.seq = 1;
        status.error_text = "x";
        std::vector<unsigned char> bytes = seal_encoded(status);
        constexpr std::size_t length_at = 8 + 5 * 8 + 3 * 4 + 1 + 8 + 4;
        for (int i = 0; i < 4; ++i) bytes[length_at + i] = 0;
        write_bytes(log, status_channel, 1, bytes);
        write(log, control_channel, 2, firtp_lcm::control_t{});
    }
    const ToolRun run = dump(file.string());
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_TRUE(contains(run.out, "1 FIRTP_STATUS ? 99 bytes\n")) << run.out;
    EXPECT_TRUE(contains(run.out, "2 FIRTP_CONTROL control_t seq=0")) << run.out;
}

// A block damaged after it was sealed (a bit of its X target) still decodes: the tool shows it,
// marked, and --count keeps it out of the seq statistics.
TEST(DumpToolErrors, CorruptedMessageIsMarked) {
    test::TempFile file{".lcmlog"};
    {
        lcm::LogFile log(file.string(), "w");
        ASSERT_TRUE(log.good());
        firtp_lcm::block_t block = test::sample_message(3);
        std::vector<unsigned char> bytes = seal_encoded(block);
        bytes[8 + 8 + 8 + 8 + 4 + 1 + 1 + 7] ^= 0x01;  // the low bit of target X
        write_bytes(log, block_channel, 1, bytes);
        write(log, block_channel, 2, test::sample_message(4));
    }
    ToolRun run = dump(file.string());
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_TRUE(contains(run.out, "1 FIRTP_BLOCK block_t seq=3 program=7 line=40 target=(-2.5000000000000004,-1,0.5) "
                                  "feed=25 tolerance=0.02 CORRUPTED: CRC mismatch (crc 0x")) << run.out;
    EXPECT_TRUE(contains(run.out, "2 FIRTP_BLOCK block_t seq=4 program=7 line=40 target=(-2.5,-1,0.5) feed=25 "
                                  "tolerance=0.02\n")) << run.out;
    run = dump("--count " + file.string());
    EXPECT_EQ(run.out,
              "FIRTP_BLOCK events=1 corrupted (CRC mismatch)\n"
              "FIRTP_BLOCK program=7 events=1 seq=4 missing=0 repeated=0 reordered=0\n");
}

TEST_F(DumpTool, ChannelFilterMatchesWholeName) {
    ToolRun run = dump("--channel 'FIRTP_AXIS.*' " + file_.string());
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 3) << run.out;

    run = dump("--channel FIRTP_AXIS " + file_.string());  // anchored, like LCM's channel names
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_EQ(run.out, "");
}

TEST_F(DumpTool, CountFindsGaps) {
    const ToolRun run = dump("--count " + file_.string());
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_EQ(run.out,
              "FIRTP_AXIS_STATE_LIVE events=3 seq=1-5 missing=2 gaps=3-4 repeated=0 reordered=0\n"
              "FIRTP_BLOCK program=7 events=6 seq=1-5 missing=0 repeated=1 reordered=1\n"
              "FIRTP_BLOCK program=8 events=1 seq=1 missing=0 repeated=0 reordered=0\n"
              "FIRTP_CONTROL events=1 seq=1 missing=0 repeated=0 reordered=0\n"
              "FIRTP_STATUS events=2 seq=1-2 missing=0 repeated=0 reordered=0\n"
              "OTHER events=1 unknown type\n");
}

TEST_F(DumpTool, CountWithFilter) {
    const ToolRun run = dump("--count --channel FIRTP_BLOCK " + file_.string());
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_EQ(run.out,
              "FIRTP_BLOCK program=7 events=6 seq=1-5 missing=0 repeated=1 reordered=1\n"
              "FIRTP_BLOCK program=8 events=1 seq=1 missing=0 repeated=0 reordered=0\n");
}

TEST(DumpToolErrors, MissingFileAndBadUsage) {
    ToolRun run = dump("/nonexistent/firtp/none.lcmlog");
    EXPECT_EQ(run.code, 1);
    EXPECT_TRUE(contains(run.out, "cannot read /nonexistent/firtp/none.lcmlog")) << run.out;

    run = dump("");
    EXPECT_EQ(run.code, 2);
    EXPECT_TRUE(contains(run.out, "no log file given")) << run.out;

    run = dump("--channel '(' x.lcmlog");
    EXPECT_EQ(run.code, 2);
    EXPECT_TRUE(contains(run.out, "bad --channel")) << run.out;

    run = dump("--help");
    EXPECT_EQ(run.code, 0);
    EXPECT_TRUE(contains(run.out, "--count")) << run.out;
}

}  // namespace
}  // namespace firtp::messages
