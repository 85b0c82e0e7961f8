// Opening an LCM transport: default URL, the receive buffer LCM 1.3.1 needs, and a clear error.
#include <firtp/messages.hpp>

#include <cstdlib>
#include <stdexcept>

namespace firtp::messages {
namespace {

constexpr const char* udpm_prefix = "udpm://";
constexpr const char* receive_buffer = "recv_buf_size=8388608";  // 8 MiB

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// "" means what LCM itself would pick: LCM_DEFAULT_URL, else our default.
std::string resolve(const std::string& url) {
    if (!url.empty()) return url;
    const char* from_environment = std::getenv("LCM_DEFAULT_URL");
    return from_environment != nullptr && *from_environment != '\0' ? from_environment : default_url();
}

std::string with_receive_buffer(const std::string& url) {
    if (!starts_with(url, udpm_prefix) || url.find("recv_buf_size=") != std::string::npos) return url;
    return url + (url.find('?') == std::string::npos ? "?" : "&") + receive_buffer;
}

// LCM prints its own reason to stderr; this repeats the usual fix in the exception.
std::string hint(const std::string& url) {
    if (starts_with(url, udpm_prefix))
        return "LCM requires a valid multicast route; on a host without a network: "
               "ip link set lo multicast on; ip route add 224.0.0.0/4 dev lo";
    if (starts_with(url, "file://")) return "the log file cannot be opened (missing, or not a readable .lcmlog)";
    if (starts_with(url, "memq://")) return "memq:// failed to start";
    return "unknown provider: use udpm://, memq:// or file://";
}

}  // namespace

std::string default_url() { return std::string(udpm_prefix) + "239.255.76.67:7667?ttl=0&" + receive_buffer; }

std::unique_ptr<lcm::LCM> open(const std::string& url) {
    const std::string full = with_receive_buffer(resolve(url));
    auto lcm = std::make_unique<lcm::LCM>(full);
    if (!lcm->good()) throw std::runtime_error("cannot open LCM at '" + full + "': " + hint(full));
    return lcm;
}

void keep_everything(lcm::Subscription* subscription) {
    if (subscription == nullptr) throw std::invalid_argument("keep_everything: no subscription");
    subscription->setQueueCapacity(0);  // 0 = unbounded
}

}  // namespace firtp::messages
