// Golden logs recorded from real runs (firtp run ... --lcm-log): the recorded blocks go into the
// component again, read with lcm::LogFile (no network), and the axis states it produces must
// equal the recorded ones. Every recorded message is intact (its crc matches).
#include "chain_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace firtp;

namespace {

struct Golden {
    const char* log;
    const char* ini;  // "" = the built-in machine
};

void PrintTo(const Golden& g, std::ostream* out) { *out << g.log; }

class Replay : public ::testing::TestWithParam<Golden> {};

template <class T>
std::vector<T> read_channel(const std::string& file, const std::string& channel) {
    lcm::LogFile log(file, "r");
    EXPECT_TRUE(log.good()) << file;
    std::vector<T> out;
    while (const lcm::LogEvent* event = log.readNextEvent()) {
        if (event->channel != channel) continue;
        const auto received = messages::receive<T>(event->data, static_cast<std::size_t>(event->datalen));
        EXPECT_FALSE(received.problem) << channel << " event " << event->eventnum << ": " << *received.problem;
        out.push_back(received.message);
    }
    return out;
}

std::size_t first_moving(const std::vector<firtp_lcm::axis_state_t>& states) {
    std::size_t i = 0;
    while (i < states.size() && states[i].line == 0) ++i;
    return i;
}

}  // namespace

TEST_P(Replay, ProducesTheRecordedAxisStates) {
    const std::string dir = FIRTP_SOURCE_DIR;
    const std::string log = dir + "/tests/replay/" + GetParam().log;
    const auto blocks = read_channel<firtp_lcm::block_t>(log, messages::block_channel);
    const auto recorded = read_channel<firtp_lcm::axis_state_t>(log, messages::axis_state_channel);
    ASSERT_FALSE(blocks.empty());
    ASSERT_GT(recorded.size(), 100u);

    const std::string ini = GetParam().ini;
    const MachineConfig machine = ini.empty() ? default_machine() : load_machine(IniFile::read(dir + "/" + ini));
    test::Chain chain(machine);
    for (const auto& b : blocks) chain.publish(b);
    // A start waits until the junction after its block is settled (the block after next, the
    // program's end, or start_wait without a block): a log of two blocks and no end starts later.
    chain.run(static_cast<int>(recorded.size()) + 10 + static_cast<int>(std::ceil(PlannerParameters{}.start_wait / machine.period)));

    const std::size_t r0 = first_moving(recorded), p0 = first_moving(chain.states);
    ASSERT_LT(r0, recorded.size());
    ASSERT_LT(p0, chain.states.size());
    std::size_t compared = 0;
    for (std::size_t i = r0, j = p0; i < recorded.size() && j < chain.states.size(); ++i, ++j, ++compared) {
        for (int a = 0; a < max_axes; ++a) {
            ASSERT_NEAR(chain.states[j].position[a], recorded[i].position[a], 1e-12) << "state " << i << " axis " << a;
            ASSERT_NEAR(chain.states[j].velocity[a], recorded[i].velocity[a], 1e-12) << "state " << i;
            ASSERT_NEAR(chain.states[j].acceleration[a], recorded[i].acceleration[a], 1e-12) << "state " << i;
        }
        ASSERT_EQ(chain.states[j].line, recorded[i].line) << "state " << i;
    }
    EXPECT_GE(compared, recorded.size() - r0 - 1);
}

INSTANTIATE_TEST_SUITE_P(Logs, Replay,
                         ::testing::Values(Golden{"diamond.lcmlog", "examples/diamond.ini"}, Golden{"corner90.lcmlog", ""}),
                         [](const auto& p) { return std::string(p.param.log).substr(0, std::string(p.param.log).find('.')); });
