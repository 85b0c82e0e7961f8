// firtp-lcm-bridge: firtp's LCM protocol for a running LinuxCNC 2.9, as a userspace HAL
// component (`loadusr -W firtp-lcm-bridge --mode ...`).
//
//   --mode firtp   firtp.so is in the HAL: the Bridge of firtp serve (component/bridge) on
//                  LinuxCNC's HAL: FIRTP_BLOCK and FIRTP_CONTROL from a host into firtp.so's block
//                  stream and control pins, with the same crc, validation, sequence and flow
//                  control; firtp.so's axis-state stream and status pins out as FIRTP_AXIS_STATE(_LIVE)
//                  and FIRTP_STATUS; and firtp.so's settings (its HAL params) as FIRTP_CONFIG
//                  every second, so that a recording replays (`firtp replay LOG`).
//   --mode motion  LinuxCNC's own motion (e.g. [TRAJ]TPMOD = firtp_tp): a `sampler` channel of the
//                  axes' pos-cmd and motion.program-line, drained and published (motion_publisher.hpp).
//
// Both only drain hal_streams written in the servo thread, so the userspace side may lag without
// losing a period; what does not fit a stream is counted and reported. Exits cleanly (hal_exit)
// on SIGTERM, as halcmd's unload sends it, and on SIGINT.
#include "loaded_config.hpp"
#include "motion_publisher.hpp"

#include <firtp/bridge.hpp>
#include <firtp/config_publisher.hpp>
#include <firtp/defaults.hpp>
#include <firtp/messages.hpp>
#include <firtp/version.hpp>

#include <boost/program_options.hpp>

#include <csignal>
#include <exception>
#include <iostream>
#include <memory>
#include <string>

namespace po = boost::program_options;

namespace {

volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int) { stop_requested = 1; }

struct Options {
    std::string mode;
    std::string name = "firtp-lcm-bridge";
    std::string url;
    int axes = 3;
    long period_ns = firtp::defaults::servo_period_ns;
    int sampler_channel = 0;
    int live_decimation = firtp::messages::default_live_decimation;
    int status_every = firtp::messages::default_status_every;
    double max_feed_scale = 2.0;
};

// False when the program should stop (help, version, a usage error); code is its exit code.
bool parse(int argc, char** argv, Options& o, int& code) {
    po::options_description d("Usage: loadusr -W firtp-lcm-bridge --mode firtp|motion [options]\nOptions");
    d.add_options()("help,h", "print this help")("version", "print the version")(
        "mode", po::value(&o.mode)->value_name("firtp|motion"),
        "firtp: firtp.so is in the HAL (blocks in, its states out); motion: LinuxCNC's motion plans "
        "(e.g. firtp_tp), its pos-cmd sampled by `sampler`")(
        "name", po::value(&o.name)->value_name("NAME"), "HAL component name and pin prefix (firtp-lcm-bridge)")(
        "lcm-url", po::value(&o.url)->value_name("URL"), "LCM provider (LCM's default group, ttl=0: this host)")(
        "axes", po::value(&o.axes)->value_name("N"), "axes, 1-9 (3): firtp's axes= or the sampler's positions")(
        "period-ns", po::value(&o.period_ns)->value_name("NS"), ("servo period ([EMCMOT]SERVO_PERIOD, " + std::to_string(firtp::defaults::servo_period_ns) + ")").c_str())(
        "sampler-channel", po::value(&o.sampler_channel)->value_name("N"), "motion: the sampler channel (0)")(
        "live-decimation", po::value(&o.live_decimation)->value_name("N"),
        ("FIRTP_AXIS_STATE_LIVE every N periods (" + std::to_string(o.live_decimation) + ")").c_str())(
        "status-every", po::value(&o.status_every)->value_name("N"),
        ("FIRTP_STATUS every N periods and on changes (" + std::to_string(o.status_every) + ")").c_str())(
        "max-feed-scale", po::value(&o.max_feed_scale)->value_name("X"),
        "firtp: highest feed override a host may set ([DISPLAY]MAX_FEED_OVERRIDE, 2)");
    try {
        po::variables_map vm;
        po::store(po::parse_command_line(argc, argv, d), vm);
        po::notify(vm);
        if (vm.count("version")) {
            std::cout << "firtp-lcm-bridge " << firtp::version << "\n";
            code = 0;
            return false;
        }
        if (vm.count("help")) {
            std::cout << d;
            code = 0;
            return false;
        }
        if (o.mode != "firtp" && o.mode != "motion") throw po::error("--mode must be firtp or motion");
        if (o.axes < 1 || o.axes > firtp::max_axes) throw po::error("--axes must be 1 to 9");
        if (o.period_ns <= 0) throw po::error("--period-ns must be positive");
        if (o.status_every < 1) throw po::error("--status-every must be at least 1");
        if (o.live_decimation < 0) throw po::error("--live-decimation must be 0 (never) or positive");
    } catch (const po::error& e) {
        std::cerr << "firtp-lcm-bridge: " << e.what() << "\n" << d;
        code = 2;
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    int code = 0;
    if (!parse(argc, argv, o, code)) return code;
    std::signal(SIGTERM, request_stop);
    std::signal(SIGINT, request_stop);
    try {
        const std::string url = o.url.empty() ? firtp::messages::default_url() : o.url;
        const auto lcm = firtp::messages::open(url);
        const double period = static_cast<double>(o.period_ns) * 1e-9;
        std::unique_ptr<firtp::Bridge> bridge;
        std::unique_ptr<firtp::MotionPublisher> motion;
        std::unique_ptr<firtp::messages::ConfigPublisher> config;
        if (o.mode == "firtp") {
            firtp::BridgeOptions b;
            b.name = o.name.c_str();
            b.axes = o.axes;
            b.period = period;
            b.live_decimation = o.live_decimation;
            b.status_every = o.status_every;
            b.max_feed_scale = o.max_feed_scale;
            bridge = std::make_unique<firtp::Bridge>(*lcm, b);  // hal_init: firtp.so's params readable
            config = std::make_unique<firtp::messages::ConfigPublisher>(*lcm, firtp::loaded_firtp_config());
        } else {
            firtp::MotionOptions m;
            m.name = o.name;
            m.axes = o.axes;
            m.period = period;
            m.sampler_channel = o.sampler_channel;
            m.live_decimation = o.live_decimation;
            m.status_every = o.status_every;
            motion = std::make_unique<firtp::MotionPublisher>(*lcm, m);
        }
        std::cout << "firtp-lcm-bridge: mode " << o.mode << ", " << o.axes << " axes, period " << period * 1e3
                  << " ms, on " << url << std::endl;
        while (!stop_requested) {
            lcm->handleTimeout(1);  // blocks and controls (mode firtp), at most 1 ms
            if (bridge) bridge->poll();
            if (motion) motion->poll();
            if (config) config->poll();
        }
        if (motion) motion->poll();  // what the servo thread wrote before the stop
        if (bridge) bridge->poll();
        std::cout << "firtp-lcm-bridge: " << (bridge ? bridge->states_published() : motion->states_published())
                  << " axis states published";
        if (bridge) std::cout << ", " << bridge->blocks_forwarded() << " blocks forwarded";
        if (motion) std::cout << ", " << motion->states_lost() << " lost";
        std::cout << std::endl;
    } catch (const std::exception& e) {
        const std::string what = e.what();  // the component's own errors start with its name
        std::cerr << (what.rfind(o.name + ": ", 0) == 0 ? "" : "firtp-lcm-bridge: ") << what << std::endl;
        return 1;
    }
    return 0;
}
