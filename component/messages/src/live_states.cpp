// The decimated live view of the axis states (FIRTP_AXIS_STATE_LIVE), one rule for every publisher.
#include <firtp/messages.hpp>

namespace firtp::messages {

bool publish_live(lcm::LCM& lcm, firtp_lcm::axis_state_t state, int decimation) {
    if (decimation <= 0 || state.tick % decimation != 0) return false;
    state.seq = state.tick / decimation;
    publish(lcm, axis_state_live_channel, state);
    return true;
}

}  // namespace firtp::messages
