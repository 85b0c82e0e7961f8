// The component's codes are the protocol's (lcm-types/README.md): the bridge copies the component's
// state and error-code pins into status_t unchanged, and attaches to its streams by these keys.
#include <firtp/bridge.hpp>

#include <firtp/hal/component_logic.hpp>
#include <firtp/hal/stream_records.hpp>

#include <type_traits>

namespace firtp {
namespace {

using Status = firtp_lcm::status_t;
constexpr auto state(ComponentState s) { return static_cast<std::int32_t>(s); }
constexpr auto error(ComponentError e) { return static_cast<std::int32_t>(e); }

static_assert(state(ComponentState::idle) == Status::IDLE && state(ComponentState::moving) == Status::MOVING &&
              state(ComponentState::holding) == Status::HOLDING && state(ComponentState::aborting) == Status::ABORTING &&
              state(ComponentState::error) == Status::ERROR && state(ComponentState::disabled) == Status::DISABLED);
static_assert(error(ComponentError::none) == Status::ERROR_NONE && error(ComponentError::bad_value) == Status::ERROR_BAD_VALUE &&
              error(ComponentError::sequence_gap) == Status::ERROR_SEQUENCE_GAP &&
              error(ComponentError::repeated) == Status::ERROR_REPEATED &&
              error(ComponentError::queue_full) == Status::ERROR_QUEUE_FULL &&
              error(ComponentError::bad_type) == Status::ERROR_BAD_TYPE &&
              error(ComponentError::not_enabled) == Status::ERROR_NOT_ENABLED &&
              error(ComponentError::lost_state) == Status::ERROR_LOST_STATE &&
              error(ComponentError::stopped_from_feedback) == Status::ERROR_STOPPED_FROM_FEEDBACK);
static_assert(stream::default_block_key == firtp_lcm::config_t::BLOCK_STREAM_KEY &&
              stream::default_state_key == firtp_lcm::config_t::STATE_STREAM_KEY);
static_assert(BridgeOptions{}.block_key == stream::default_block_key &&
              BridgeOptions{}.state_key == stream::default_state_key);
// Every axis state names the control applied in its period by that control's own session and seq.
static_assert(std::is_same_v<decltype(firtp_lcm::axis_state_t::control_session), decltype(firtp_lcm::control_t::session)> &&
              std::is_same_v<decltype(firtp_lcm::axis_state_t::control_seq), decltype(firtp_lcm::control_t::seq)>);

}  // namespace
}  // namespace firtp
