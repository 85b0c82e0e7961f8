// The component side in this process (hal-shim + firtp.so + bridge) on memq://, stepped one
// servo period at a time, with every message it sends collected (each checked: the component's
// messages are sealed) and every message sent to it sealed, unless a test damages it on purpose.
#pragma once

#include <firtp/machine.hpp>
#include <firtp/messages.hpp>
#include <firtp/in_process_component.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace firtp::test {

struct Chain {
    std::unique_ptr<lcm::LCM> lcm = messages::open("memq://");
    std::unique_ptr<InProcessComponent> chain;
    std::vector<firtp_lcm::axis_state_t> states;
    std::vector<firtp_lcm::status_t> statuses;
    std::int64_t control_seq = 0;

    explicit Chain(const MachineConfig& machine, const InProcessSettings& settings = {}) {
        chain = std::make_unique<InProcessComponent>(*lcm, machine, default_module_path(), settings);
        messages::keep_everything(lcm->subscribe(messages::axis_state_channel, &Chain::on_state, this));
        messages::keep_everything(lcm->subscribe(messages::status_channel, &Chain::on_status, this));
    }
    template <class Message> static Message intact(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
        const auto received = messages::receive<Message>(buffer->data, buffer->data_size);
        EXPECT_FALSE(received.problem) << channel << ": " << *received.problem;
        return received.message;
    }
    void on_state(const lcm::ReceiveBuffer* b, const std::string& c) { states.push_back(intact<firtp_lcm::axis_state_t>(b, c)); }
    void on_status(const lcm::ReceiveBuffer* b, const std::string& c) { statuses.push_back(intact<firtp_lcm::status_t>(b, c)); }

    void publish(firtp_lcm::block_t block) { messages::publish(*lcm, messages::block_channel, block); }
    // Bytes as they are, e.g. a sealed message damaged in transit.
    void publish_bytes(const char* channel, const std::vector<std::uint8_t>& bytes) {
        lcm->publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
    }
    void control(double feed, bool hold, bool abort, std::int64_t session = 1) {
        firtp_lcm::control_t c{};
        c.session = session;
        c.seq = ++control_seq;
        c.feed_scale = feed;
        c.hold = hold;
        c.abort = abort;
        messages::publish(*lcm, messages::control_channel, c);
    }
    // Delivers what was published, runs `periods` servo periods and delivers their messages.
    void run(int periods) {
        for (int k = 0; k < periods; ++k) {
            while (lcm->handleTimeout(0) > 0) {
            }
            chain->step();
            chain->poll();
        }
        while (lcm->handleTimeout(0) > 0) {
        }
    }
    const firtp_lcm::status_t& status() const { return statuses.back(); }
    AxisVector position() const {
        AxisVector p = AxisVector::Zero();
        for (int a = 0; a < max_axes; ++a) p[a] = states.back().position[a];
        return p;
    }
};

inline firtp_lcm::block_t block_message(double x, double y, std::int64_t program, std::int64_t seq, int line,
                                        double feed = 100.0) {
    Block b;
    b.target[0] = x;
    b.target[1] = y;
    b.feed = feed;
    b.tolerance = 0.05;
    b.line = line;
    return messages::to_message(b, program, seq, 0);
}

// Short filters and no axis limits: for tests about messages, not motion.
inline MachineConfig message_machine() {
    MachineConfig m = default_machine();
    m.given_times = {0.02, 0.01};
    m.limits = MachineLimits{};
    return m;
}

}  // namespace firtp::test
