// Faults between the host and the component, through the real chain (firtp host's Host, LCM,
// firtp-bridge, firtp.so under hal-shim), deterministic: each side has its own memq:// LCM and a
// relay between them drops, duplicates, delays (so reorders) and corrupts messages (a damaged type
// hash, a truncation, or one bit of the payload: a block's target or feed, a control's feed
// override, a status's next_seq or queue_free, which still decode as valid messages), stepped one
// servo period at a time with a clock that advances one period per step. Also: the host dying
// mid-program and a restarted host resuming it, and the component restarting under a running host.
//
// Measured on the component's own axis states (every period, not through the faulty link): every
// block is forwarded to the component exactly once (bridge count, status next_seq), the machine
// ends exactly on the last target, velocity and acceleration stay within the axis limits at every
// sample (a stop for want of blocks included), and every corner is within its tolerance.
#include "chain_fixture.hpp"

#include <firtp/host.hpp>
#include <firtp/measure.hpp>
#include <firtp/recorded_states.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace firtp;

namespace {

struct Faults {
    double drop = 0.0, duplicate = 0.0, corrupt = 0.0;
    int max_delay = 0;  // periods; a random delay per message reorders them
    int min_delay = 0;
};

// Where the fields a payload corruption damages are in the encodings (after the 8-byte fingerprint).
constexpr std::size_t block_target_at = 8 + 8 + 8 + 8 + 4 + 1 + 1;  // utime, program, seq, line, kinds
constexpr std::size_t block_feed_at = block_target_at + 9 * 8;
constexpr std::size_t control_feed_scale_at = 8 + 8 + 8 + 8;        // utime, session, seq
constexpr std::size_t status_next_seq_at = 8 + 4 * 8;               // utime, seq, tick, program
constexpr std::size_t status_queue_free_at = status_next_seq_at + 8 + 4;

// One direction of the network: messages on `from` matching `channels` reach `to` after the
// faults; pump(now) delivers what is due.
class Link {
public:
    Link(lcm::LCM& from, lcm::LCM& to, const std::string& channels, Faults faults, std::uint64_t seed)
        : to_(&to), faults_(faults), rng_(seed) {
        messages::keep_everything(from.subscribe(channels, &Link::on_message, this));
    }
    void pump(std::int64_t now) {
        std::stable_sort(queue_.begin(), queue_.end(), [](const Pending& a, const Pending& b) { return a.due < b.due; });
        std::size_t n = 0;
        while (n < queue_.size() && queue_[n].due <= now) {
            to_->publish(queue_[n].channel, queue_[n].bytes.data(), static_cast<unsigned>(queue_[n].bytes.size()));
            ++delivered;
            damaged_delivered += queue_[n].damaged;
            ++n;
        }
        queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(n));
    }
    void set_faults(const Faults& f) { faults_ = f; }
    void set_now(std::int64_t now) { now_ = now; }

    std::int64_t delivered = 0, dropped = 0, duplicated = 0, corrupted = 0, delayed = 0;
    std::int64_t hash_damaged = 0, truncated = 0, payload_damaged = 0;  // the kinds of corruption
    std::int64_t damaged_delivered = 0;  // corrupted copies delivered (a duplicate of one counts twice)

private:
    struct Pending {
        std::int64_t due;
        std::string channel;
        std::vector<std::uint8_t> bytes;
        bool damaged;
    };
    double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
    void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
        std::vector<std::uint8_t> bytes(static_cast<const std::uint8_t*>(buffer->data),
                                        static_cast<const std::uint8_t*>(buffer->data) + buffer->data_size);
        if (unit() < faults_.drop) {
            ++dropped;
            return;
        }
        const bool damaged = unit() < faults_.corrupt;
        if (damaged) {
            ++corrupted;
            const double kind = unit();
            if (kind < 0.25 && bytes.size() > 8) {  // the kinds LCM's decode notices
                ++hash_damaged;
                bytes[static_cast<std::size_t>(unit() * 8)] ^= 0x5a;
            } else if (kind < 0.5) {
                ++truncated;
                bytes.resize(static_cast<std::size_t>(unit() * static_cast<double>(bytes.size())));
            } else {  // type hash and length intact: only the crc tells
                ++payload_damaged;
                flip_payload_bit(channel, bytes);
            }
        }
        const int copies = unit() < faults_.duplicate ? 2 : 1;
        duplicated += copies - 1;
        for (int c = 0; c < copies; ++c) {
            const auto delay =
                faults_.min_delay + static_cast<std::int64_t>(unit() * (faults_.max_delay - faults_.min_delay + 1));
            delayed += delay > 0;
            queue_.push_back({now_ + delay, channel, bytes, damaged});
        }
    }

    // One bit of a field that matters, so the message still decodes as a valid one: a low
    // mantissa bit (a change of at most 3 %) of a block's X, Y or Z target or its feed, or of a
    // control's feed override; a status's next_seq or queue_free (bits 0-3); else any payload bit.
    void flip_payload_bit(const std::string& channel, std::vector<std::uint8_t>& bytes) {
        const auto pick = [this](int n) { return static_cast<std::size_t>(unit() * n); };
        std::size_t field = 0;  // where the big-endian field starts
        int low_bits = 0;       // flip one of its lowest low_bits bits
        if (channel == messages::block_channel) {
            const std::size_t which = pick(4);
            field = which < 3 ? block_target_at + 8 * which : block_feed_at;
            low_bits = 48;
        } else if (channel == messages::control_channel) {
            field = control_feed_scale_at;
            low_bits = 48;
        } else if (channel == messages::status_channel) {
            field = unit() < 0.5 ? status_next_seq_at : status_queue_free_at;
            low_bits = 4;
        }
        const std::size_t size = field == status_queue_free_at ? 4 : 8;
        if (low_bits == 0 || field + size > bytes.size()) {
            const std::size_t at = 8 + pick(static_cast<int>(bytes.size()) - 8);
            bytes[at] ^= static_cast<std::uint8_t>(1u << pick(8));
            return;
        }
        const std::size_t bit = pick(low_bits);
        bytes[field + size - 1 - bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    }

    lcm::LCM* to_;
    Faults faults_;
    std::mt19937_64 rng_;
    std::int64_t now_ = 0;
    std::vector<Pending> queue_;
};

// Random moves in X Y Z, 0.3-25 mm, 20-250 mm/s, tolerance 0.01-0.1 mm, absolute targets; or
// (short_moves) a curve of 0.3-2 mm chords turning gently, at 150-250 mm/s (a block every few ms).
Program random_program(std::uint64_t seed, int blocks, bool short_moves = false) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Program p;
    p.file = "faults.ngc";
    AxisVector at = AxisVector::Zero(), heading = AxisVector::Unit(0);
    for (int i = 0; i < blocks; ++i) {
        Block b;
        const double length = short_moves ? 0.3 + 1.7 * unit(rng) : unit(rng) < 0.3 ? 0.3 + unit(rng) : 5.0 + 20.0 * unit(rng);
        AxisVector d = AxisVector::Zero();
        for (int a = 0; a < 3; ++a) d[a] = unit(rng) - 0.5;
        if (short_moves) d = heading + 0.1 * d;
        heading = d.normalized();
        b.target = at + heading * length;
        b.feed = short_moves ? 150 + 100 * unit(rng) : 20 + 230 * unit(rng);
        b.tolerance = 0.01 + 0.09 * unit(rng);
        b.termination = unit(rng) < 0.05 ? Termination::exact_stop : Termination::blend;
        b.line = 10 + i;
        p.blocks.push_back(b);
        at = b.target;
    }
    return p;
}

// The component side on its LCM, the host on another, relays between them; one period per step.
struct Network {
    MachineConfig machine = default_machine();
    std::unique_ptr<lcm::LCM> host_lcm = messages::open("memq://");
    std::unique_ptr<lcm::LCM> component_lcm = messages::open("memq://");
    std::unique_ptr<InProcessComponent> chain;
    Link to_component, to_host;
    std::vector<firtp_lcm::axis_state_t> states;  // the component's, every period (not through the link)
    std::vector<firtp_lcm::status_t> statuses;    // the component's, as sent
    std::int64_t now = 0;

    // A component that holds 16 blocks and a stream of 16: the host can be about 30 blocks ahead,
    // so a program of 60 or more is still being sent while it runs.
    static InProcessSettings small() {
        InProcessSettings s;
        s.queue = 16;
        s.stream_depth = 16;
        return s;
    }

    Network(Faults down, Faults up, std::uint64_t seed)
        : chain(std::make_unique<InProcessComponent>(*component_lcm, machine, default_module_path(), small())),
          to_component(*host_lcm, *component_lcm, "FIRTP_BLOCK|FIRTP_CONTROL", down, seed),
          to_host(*component_lcm, *host_lcm, "FIRTP_STATUS", up, seed + 1) {
        messages::keep_everything(component_lcm->subscribe(messages::axis_state_channel, &Network::on_state, this));
        messages::keep_everything(component_lcm->subscribe(messages::status_channel, &Network::on_status, this));
        messages::keep_everything(component_lcm->subscribe(messages::block_channel, &Network::on_block, this));
        messages::keep_everything(component_lcm->subscribe(messages::control_channel, &Network::on_control, this));
    }
    void on_state(const lcm::ReceiveBuffer* b, const std::string& c) { states.push_back(test::Chain::intact<firtp_lcm::axis_state_t>(b, c)); }
    void on_status(const lcm::ReceiveBuffer* b, const std::string& c) { statuses.push_back(test::Chain::intact<firtp_lcm::status_t>(b, c)); }

    // What reaches the component's LCM through the link, as the bridge sees it: an intact block is
    // the program's own; a damaged one that still decodes as a valid block (the danger without a
    // crc) is counted and must have been refused.
    struct Delivered {
        std::int64_t intact = 0, refused = 0, intact_but_wrong = 0;
        std::int64_t valid_but_wrong = 0;  // refused, yet it decodes as a valid message that differs
    } blocks_in, controls_in;
    const Program* program = nullptr;  // the one the host sends
    double feed_scale = 1.0;           // the override it sends

    static bool same_block(const firtp_lcm::block_t& m, const Block& b) {
        for (int a = 0; a < max_axes; ++a)
            if (m.target[a] != b.target[a]) return false;
        return m.feed == b.feed && m.tolerance == b.tolerance && m.line == b.line;
    }
    void on_block(const lcm::ReceiveBuffer* buffer, const std::string&) {
        if (program == nullptr) return;
        const auto r = messages::receive<firtp_lcm::block_t>(buffer->data, buffer->data_size);
        const bool known = r.decoded && r.message.seq >= 1 && r.message.seq <= std::ssize(program->blocks);
        const bool ours = known && same_block(r.message, program->blocks[static_cast<std::size_t>(r.message.seq - 1)]);
        if (!r.problem) {
            ++blocks_in.intact;
            blocks_in.intact_but_wrong += !ours;
            return;
        }
        ++blocks_in.refused;
        blocks_in.valid_but_wrong += r.decoded && !messages::validate(r.message) && !ours;
    }
    void on_control(const lcm::ReceiveBuffer* buffer, const std::string&) {
        const auto r = messages::receive<firtp_lcm::control_t>(buffer->data, buffer->data_size);
        if (!r.problem) {
            ++controls_in.intact;
            controls_in.intact_but_wrong += r.message.feed_scale != feed_scale;
            return;
        }
        ++controls_in.refused;
        controls_in.valid_but_wrong += r.decoded && std::isfinite(r.message.feed_scale) && r.message.feed_scale >= 0 &&
                                       r.message.feed_scale != feed_scale;
    }

    host::HostOptions options(std::int64_t program_id) {
        host::HostOptions o;
        o.program_id = program_id;
        o.clock = [this] { return host::Clock::time_point(std::chrono::milliseconds(now)); };
        return o;
    }
    // One period: the host, the network, the servo thread, the bridge.
    void step(host::Host* h) {
        if (h) h->step();
        to_component.set_now(now);
        to_host.set_now(now);
        to_component.pump(now);
        while (component_lcm->handleTimeout(0) > 0) {
        }
        chain->step();
        chain->poll();
        while (component_lcm->handleTimeout(0) > 0) {
        }
        to_host.pump(now);
        ++now;
    }
    host::Result run(host::Host& h, int max_periods, int hold_from = -1, int hold_to = -1) {
        for (int k = 0; k < max_periods && h.result() == host::Result::running; ++k) {
            if (k == hold_from) h.hold(true);
            if (k == hold_to) h.hold(false);
            step(&h);
        }
        return h.result();
    }
    void idle(int periods) {
        for (int k = 0; k < periods; ++k) step(nullptr);
    }
    AxisVector position() const {
        AxisVector p = AxisVector::Zero();
        for (int a = 0; a < max_axes; ++a) p[a] = states.back().position[a];
        return p;
    }
};

// |v| / v_max and |a| / a_max at every sample the component produced: at most 1 (+ rounding).
double worst_limit_ratio(const std::vector<firtp_lcm::axis_state_t>& states, const MachineLimits& l) {
    double worst = 0.0;
    for (const auto& s : states)
        for (int a = 0; a < l.axes; ++a)
            worst = std::max({worst, std::abs(s.velocity[a]) / l.axis[a].max_velocity,
                              std::abs(s.acceleration[a]) / l.axis[a].max_acceleration});
    return worst;
}

// Corner errors over tolerance, worst, measured on the samples against the program.
double worst_corner_share(const Network& net, const Program& program) {
    const std::vector<AxisState> samples = samples_from_axis_states(net.states, net.machine.period);
    std::vector<AxisVector> points{program.start};
    for (const Block& b : program.blocks) points.push_back(b.target);
    const Measured m = measure(samples, points, net.machine.period);
    double worst = 0.0;
    for (std::size_t c = 0; c < m.corner_errors.size(); ++c)
        worst = std::max(worst, m.corner_errors[c] / program.blocks[c].tolerance);
    return worst;
}

void expect_exactly_once_and_on_target(const Network& net, const Program& program, std::int64_t program_id) {
    EXPECT_EQ(net.chain->bridge().blocks_forwarded(), static_cast<std::int64_t>(program.blocks.size()));
    ASSERT_FALSE(net.statuses.empty());
    EXPECT_EQ(net.statuses.back().program, program_id);
    EXPECT_EQ(net.statuses.back().next_seq, static_cast<std::int64_t>(program.blocks.size()) + 1);
    ASSERT_FALSE(net.states.empty());
    const AxisVector end = net.position();
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(end[a], program.blocks.back().target[a], 1e-9);
    EXPECT_LE(worst_limit_ratio(net.states, net.machine.limits), 1.0 + 1e-6);
}

}  // namespace

// Blocks, controls and statuses dropped (10 %), duplicated (5 %), delayed up to 30 ms (so
// reordered) and corrupted (6 %: a quarter a damaged type hash, a quarter truncated, half one bit
// of the payload: a block's target or feed, a control's feed override, a status's next_seq or
// queue_free, still a valid message to LCM's decode), with a hold sent over the same link:
// the crc refuses every corrupted copy (a block as if lost, reported; a status dropped by the
// host), go-back-N and the republished controls repair it all; nothing runs twice, nothing is
// skipped, no damaged target, feed or override is used, the path keeps its tolerances.
TEST(LcmFaults, LossyLinkDeliversEveryBlockOnceAndTheMachineStaysOnThePath) {
    Faults down{0.10, 0.05, 0.06, 30};
    Faults up{0.10, 0.05, 0.06, 20};
    Network net(down, up, 11);
    const Program program = random_program(3, 150);
    net.program = &program;
    host::Host h(*net.host_lcm, program, net.options(501));
    EXPECT_EQ(net.run(h, 600000, 3000, 4500), host::Result::done) << h.error();
    expect_exactly_once_and_on_target(net, program, 501);
    const double corners = worst_corner_share(net, program);
    EXPECT_LE(corners, 1.0 + 1e-9);  // off the sample grid after the hold it was 1.0011 (fixed: TimeScale::trim)
    const host::Statistics s = h.statistics();
    const Link& down_link = net.to_component;
    const Link& up_link = net.to_host;
    std::printf("lossy link: %lld blocks published for %zu (%lld go-backs), %lld refused by the bridge; down: %lld "
                "dropped, %lld duplicated, %lld delayed, %lld corrupted (%lld type hash, %lld truncated, %lld payload); "
                "up: %lld dropped, %lld duplicated, %lld corrupted (%lld type hash, %lld truncated, %lld payload); "
                "%lld periods; worst corner %.6f of its tolerance; |v|,|a| <= %.4f of the limits\n",
                static_cast<long long>(s.blocks_published), program.blocks.size(), static_cast<long long>(s.go_backs),
                static_cast<long long>(s.rejected), static_cast<long long>(down_link.dropped),
                static_cast<long long>(down_link.duplicated), static_cast<long long>(down_link.delayed),
                static_cast<long long>(down_link.corrupted), static_cast<long long>(down_link.hash_damaged),
                static_cast<long long>(down_link.truncated), static_cast<long long>(down_link.payload_damaged),
                static_cast<long long>(up_link.dropped), static_cast<long long>(up_link.duplicated),
                static_cast<long long>(up_link.corrupted), static_cast<long long>(up_link.hash_damaged),
                static_cast<long long>(up_link.truncated), static_cast<long long>(up_link.payload_damaged),
                static_cast<long long>(net.now), corners, worst_limit_ratio(net.states, net.machine.limits));
    std::printf("lossy link, corruption: %lld corrupted copies reached the bridge, %lld refused as corrupted "
                "(blocks: %lld intact, %lld refused, %lld of them valid blocks with another target or feed; "
                "controls: %lld intact, %lld refused, %lld of them valid with another override); %lld corrupted "
                "statuses reached the host, %lld dropped\n",
                static_cast<long long>(down_link.damaged_delivered),
                static_cast<long long>(net.chain->bridge().messages_corrupted()),
                static_cast<long long>(net.blocks_in.intact), static_cast<long long>(net.blocks_in.refused),
                static_cast<long long>(net.blocks_in.valid_but_wrong), static_cast<long long>(net.controls_in.intact),
                static_cast<long long>(net.controls_in.refused), static_cast<long long>(net.controls_in.valid_but_wrong),
                static_cast<long long>(up_link.damaged_delivered), static_cast<long long>(s.corrupted_dropped));
    EXPECT_GT(down_link.dropped, 10);
    EXPECT_GT(down_link.duplicated, 5);
    EXPECT_GT(down_link.payload_damaged, 5);
    EXPECT_GT(down_link.hash_damaged + down_link.truncated, 3);
    EXPECT_GT(up_link.dropped, 10);
    EXPECT_GT(up_link.payload_damaged, 3);
    EXPECT_GT(s.go_backs, 3);

    // Every corrupted copy that reached the component was refused as corrupted, and nothing else.
    EXPECT_EQ(net.chain->bridge().messages_corrupted(), down_link.damaged_delivered);
    EXPECT_EQ(net.statuses.back().corrupted, down_link.damaged_delivered);
    EXPECT_EQ(net.blocks_in.refused + net.controls_in.refused, down_link.damaged_delivered);
    EXPECT_EQ(net.blocks_in.intact_but_wrong, 0);
    EXPECT_EQ(net.controls_in.intact_but_wrong, 0);
    EXPECT_GT(net.blocks_in.valid_but_wrong, 3);    // without the crc these would have run
    EXPECT_GT(net.controls_in.valid_but_wrong, 0);  // and these changed the feed override
    // Reported: the status named a refused block and the crc.
    bool reported = false;
    for (const auto& st : net.statuses)
        reported = reported || (st.error_code == firtp_lcm::status_t::ERROR_CORRUPTED &&
                                st.error_text.find("block seq ") == 0 &&
                                st.error_text.find(": corrupted: CRC mismatch (crc 0x") != std::string::npos &&
                                st.error_text.find("; refused, expected seq ") != std::string::npos);
    EXPECT_TRUE(reported);
    // The host dropped the corrupted statuses it read (those of its last period it never read).
    EXPECT_GT(s.corrupted_dropped, 3);
    EXPECT_LE(s.corrupted_dropped, up_link.damaged_delivered);
    EXPECT_GT(s.corrupted_refused, 3);  // as the host last read it in a status
    EXPECT_LE(s.corrupted_refused, down_link.damaged_delivered);
}

// For 3 s in the middle of the program every message to the component (the host's resends too) is
// delayed by 3 s, longer than the 1.5 s of motion it has queued: the component plans
// nothing it did not receive, so it comes to rest exactly at the end of the last block it has,
// within the limits; the host's resends go out, the late copies arrive after them and are refused
// as repeats, and the program goes on: each block once.
TEST(LcmFaults, DelayedBlocksStopTheMachineAtTheLastBlockAndItGoesOn) {
    Network net({}, {}, 21);
    const Program program = random_program(4, 300, true);  // about 1.5 s of motion
    host::Host h(*net.host_lcm, program, net.options(601));
    for (int k = 0; k < 300; ++k) net.step(&h);
    net.to_component.set_faults({0.0, 0.0, 0.0, 3000, 3000});
    bool rested = false;  // the machine came to rest on the last block it had while it waited
    for (int k = 0; k < 6000 && h.result() == host::Result::running; ++k) {
        if (k == 3000) net.to_component.set_faults({});
        net.step(&h);
        const firtp_lcm::status_t& s = net.statuses.back();
        if (rested || s.state != firtp_lcm::status_t::IDLE || s.queue_depth != 0 || s.next_seq < 2) continue;
        const AxisVector at = net.position();
        rested = true;
        for (int a = 0; a < 3; ++a)
            EXPECT_EQ(at[a], program.blocks[static_cast<std::size_t>(s.next_seq - 2)].target[a]) << "seq " << s.next_seq - 1;
    }
    EXPECT_TRUE(rested);
    ASSERT_EQ(net.run(h, 600000), host::Result::done) << h.error();
    expect_exactly_once_and_on_target(net, program, 601);
    EXPECT_LE(worst_corner_share(net, program), 1.0 + 1e-9);
    EXPECT_GT(net.to_component.delayed, 5);
    std::printf("delayed link: %lld blocks published for %zu, %lld go-backs, %lld refused (late copies)\n",
                static_cast<long long>(h.statistics().blocks_published), program.blocks.size(),
                static_cast<long long>(h.statistics().go_backs), static_cast<long long>(h.statistics().rejected));
}

// The host dies mid-program (it stops sending and never answers again). The component finishes
// the blocks it has and rests exactly on the last one's end, within the limits. A restarted host
// with the same program (same id) resumes from the component's next_seq: the blocks already run
// are not sent again (the component would refuse them as repeats anyway), the rest run once.
TEST(LcmFaults, HostDiesAndARestartedHostResumesTheProgramExactlyOnce) {
    Network net({}, {}, 31);
    const Program program = random_program(5, 120);
    auto first = std::make_unique<host::Host>(*net.host_lcm, program, net.options(701));
    for (int k = 0; k < 2500; ++k) net.step(first.get());
    ASSERT_EQ(first->result(), host::Result::running);
    const std::int64_t sent = static_cast<std::int64_t>(first->progress().sent);
    first.reset();  // the host process is gone
    for (int k = 0; k < 60000 && !(net.statuses.back().state == firtp_lcm::status_t::IDLE && k > 100); ++k) net.idle(1);
    const firtp_lcm::status_t& rest = net.statuses.back();
    EXPECT_EQ(rest.state, firtp_lcm::status_t::IDLE);
    EXPECT_EQ(rest.queue_depth, 0);
    const std::int64_t ran = rest.next_seq - 1;
    EXPECT_GT(ran, 10);
    EXPECT_LT(ran, static_cast<std::int64_t>(program.blocks.size()));
    EXPECT_LE(ran, sent);
    const AxisVector at = net.position();
    for (int a = 0; a < 3; ++a) EXPECT_EQ(at[a], program.blocks[static_cast<std::size_t>(ran - 1)].target[a]);
    EXPECT_LE(worst_limit_ratio(net.states, net.machine.limits), 1.0 + 1e-6);

    host::Host second(*net.host_lcm, program, net.options(701));
    EXPECT_EQ(net.run(second, 600000), host::Result::done) << second.error();
    expect_exactly_once_and_on_target(net, program, 701);
    EXPECT_LE(worst_corner_share(net, program), 1.0 + 1e-9);
    std::printf("host died after %lld of %zu blocks were accepted (%lld sent); the restarted host published %lld "
                "(its first window before a status: repeats, refused); the bridge forwarded %lld in all\n",
                static_cast<long long>(ran), program.blocks.size(), static_cast<long long>(sent),
                static_cast<long long>(second.statistics().blocks_published),
                static_cast<long long>(net.chain->bridge().blocks_forwarded()));
}

// The component restarts mid-program (firtp.so and the bridge unloaded and loaded again, as a
// crashed and restarted HAL would): it has lost the program, and must not run the rest of it as if
// nothing had happened. The host's next blocks are a gap for the new component (it expects seq 1
// of a new program), so nothing of the old program runs there, and the host fails once the
// component's statuses have named another program for 1 s. (Before, the host waited for ever,
// reporting nothing: it had no block outstanding, so its resend timeout never fired.) This chain
// has no machine, so firtp.axis.N.pos-fb is unconnected and the new component starts at 0; with
// the feedback connected it starts from the axes and brakes them (restart_test.cpp).
TEST(LcmFaults, ComponentRestartMidProgramRunsNothingOfItAndTheHostFails) {
    Network net({}, {}, 41);
    const Program program = random_program(6, 120);
    host::Host h(*net.host_lcm, program, net.options(801));
    for (int k = 0; k < 3000; ++k) net.step(&h);
    ASSERT_EQ(h.result(), host::Result::running);
    const AxisVector before = net.position();
    const std::size_t states_before = net.states.size();
    net.chain.reset();  // the component side goes away ...
    net.chain = std::make_unique<InProcessComponent>(*net.component_lcm, net.machine, default_module_path(), Network::small());
    EXPECT_EQ(net.run(h, 60000), host::Result::failed);
    EXPECT_NE(h.error().find("the component no longer has program 801"), std::string::npos) << h.error();
    EXPECT_LT(net.now - 3000, 2000);  // reported within 2 s
    EXPECT_EQ(net.chain->bridge().blocks_forwarded(), 0);  // nothing of the old program ran
    ASSERT_GT(net.states.size(), states_before);
    const firtp_lcm::axis_state_t& first = net.states[states_before];
    double jump = 0.0;
    for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(first.position[a], 0.0);
        jump = std::max(jump, std::abs(before[a]));
    }
    EXPECT_EQ(net.statuses.back().next_seq, 1);
    std::printf("component restarted after %lld periods: the host failed after %.1f s (%s); the new component ran no "
                "block; its output started at the origin, %.1f mm from where the old one was\n",
                3000LL, static_cast<double>(net.now - 3000) / 1000.0, h.error().c_str(), jump);
}
