// firtp: FIR-filter corner smoothing as a LinuxCNC-style HAL component.
//
//   loadrt firtp [axes=3] [stages=2] [t1=S t2=S t3=S t4=S] [tolerance=MM] [meaning=corner|contour]
//                [period_ns=1000000] [queue=1024] [max_blocks=32] [plan_budget_us=250] [block_key=K]
//                [state_key=K] [max_velocity=V,V,..] [max_acceleration=A,..] [max_jerk=J,..]
//                [stream_depth=4096] [max_feed_override=1] [rate_reserve=0.2] [brake_speed=1]
//   addf firtp.update servo-thread
//
// Every load-time setting, as in effect, is a read-only param: halcmd show param firtp (man 9 firtp).
//
// Principle of operation (see component_logic.hpp): blocks come in through the firtp.block.*
// pins with a strobe/ack handshake, or many per period through the hal_stream `block_key` that
// the LCM bridge writes. Each is checked and planned when accepted; every period firtp.update
// advances the FIR chain and drives firtp.axis.N.{pos,vel,acc}-cmd. Every period's axis state
// also goes to the hal_stream `state_key` for recording. While firtp.enable is off the outputs
// follow firtp.axis.N.pos-fb; when it rises, and at the first period, the component starts from
// the feedback, and brakes within the limits from firtp.axis.N.vel-fb if the axes move (a restart
// while moving). Connect the feedback as LinuxCNC's joint.N.motor-pos-fb; in a simulation, net
// pos-cmd to pos-fb. Without t1 every move is smoothed at the limits max_acceleration (an axis
// without one is absent: its moves are refused) and max_jerk; with t1 (and t2.. for more
// stages) the paper's fixed chain smooths every block instead.
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

#include <firtp/hal/component_logic.hpp>
#include <firtp/hal/control_pins.hpp>
#include <firtp/hal/module_number.hpp>
#include <firtp/hal/pin_table.hpp>
#include <firtp/hal/hal_pin_access.hpp>
#include <firtp/hal/stream_records.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>

MODULE_AUTHOR("firtp");
MODULE_DESCRIPTION("FIR-filter kinematic corner smoothing trajectory planner (Sencer et al. 2015)");
MODULE_LICENSE("GPL");

static int axes = 3;
RTAPI_MP_INT(axes, "number of axes, 1..9 (X Y Z A B C U V W)");
static int stages = 2;
RTAPI_MP_INT(stages, "FIR stages of the fixed chain (with t1), 1..4");
static char* t1 = nullptr;
RTAPI_MP_STRING(t1, "T1 in seconds (Eq. 1-2), the longest stage: the paper's fixed chain; unset: smoothing at the limits");
static char* t2 = nullptr;
RTAPI_MP_STRING(t2, "T2 in seconds");
static char* t3 = nullptr;
RTAPI_MP_STRING(t3, "T3 in seconds");
static char* t4 = nullptr;
RTAPI_MP_STRING(t4, "T4 in seconds");
static char* tolerance = nullptr;
RTAPI_MP_STRING(tolerance, "default corner tolerance in machine units for pin blocks with tolerance 0 (" FIRTP_DEFAULT_TOLERANCE_TEXT ")");
static char* meaning = nullptr;
RTAPI_MP_STRING(meaning, "what the tolerance bounds: corner (closest approach to the corner point) or contour");
static long period_ns = firtp::defaults::servo_period_ns;
RTAPI_MP_LONG(period_ns, "period of the thread firtp.update runs in, ns");
static char* max_velocity = nullptr;
RTAPI_MP_STRING(max_velocity, "per-axis velocity limits, units/s, comma separated (0: none)");
static char* max_acceleration = nullptr;
RTAPI_MP_STRING(max_acceleration, "per-axis acceleration limits, units/s^2, comma separated");
static char* max_jerk = nullptr;
RTAPI_MP_STRING(max_jerk, "per-axis jerk limits, units/s^3, comma separated");
static int plan_budget_us = firtp::defaults::plan_budget_us;
RTAPI_MP_INT(plan_budget_us, "planning time per period after the first block, us (" FIRTP_DEFAULT_PLAN_BUDGET_US_TEXT "; 0: up to max_blocks)");
static int queue = firtp::defaults::queue;
RTAPI_MP_INT(queue, "blocks the planner holds at once");
static int max_blocks = firtp::defaults::max_blocks;
RTAPI_MP_INT(max_blocks, "stream blocks planned per period at most");
static long block_key = firtp::stream::default_block_key;
RTAPI_MP_LONG(block_key, "hal_stream key of the block stream (0: pins only)");
static long state_key = firtp::stream::default_state_key;
RTAPI_MP_LONG(state_key, "hal_stream key of the axis-state stream (0: none)");
static char* max_feed_override = nullptr;
RTAPI_MP_STRING(max_feed_override, "highest feed-scale, >= 1 ([DISPLAY]MAX_FEED_OVERRIDE); limits hold up to it (" FIRTP_DEFAULT_MAX_FEED_OVERRIDE_TEXT ")");
static char* rate_reserve = nullptr;
RTAPI_MP_STRING(rate_reserve, "fixed chain: share of acceleration and jerk limits kept for override and hold ramps (" FIRTP_DEFAULT_RATE_RESERVE_TEXT ")");
static int stream_depth = firtp::defaults::stream_depth;
RTAPI_MP_INT(stream_depth, "blocks the block stream holds, periods the axis-state stream holds");
static char* brake_speed = nullptr;
RTAPI_MP_STRING(brake_speed, "vel-fb speed, units/s, above which a start or enable brakes from the feedback (" FIRTP_DEFAULT_BRAKE_SPEED_TEXT ")");

namespace {

// The pins, from pin_table.hpp.
#define FIRTP_PIN_MEMBER(member, name, type, direction, doc) hal_##type##_t* member;
struct AxisPins {
    FIRTP_AXIS_PINS(FIRTP_PIN_MEMBER)
};

struct Pins {
    AxisPins axis[firtp::max_axes];
    hal_float_t* block_target[firtp::max_axes];
    FIRTP_PINS(FIRTP_PIN_MEMBER)
};
#undef FIRTP_PIN_MEMBER

// The load-time settings as read-only HAL params (halcmd show param firtp), as in effect: after
// the defaults and checks of settings_from_parameters.
struct AxisParams {
    hal_float_t max_velocity;
    hal_float_t max_acceleration;
    hal_float_t max_jerk;
};

struct Params {
    hal_s32_t axes;
    hal_bit_t fixed_chain;     // 1: the paper's chain (t1 given), 0: every move smoothed at the limits
    hal_s32_t stages;          // of the fixed chain, 0 without it
    hal_float_t t[firtp::max_stages];  // s, 0 unused
    hal_float_t tolerance;
    hal_bit_t contour;         // 1: meaning=contour, 0: corner
    hal_s32_t period_ns;
    hal_s32_t queue;
    hal_s32_t max_blocks;
    hal_s32_t plan_budget_us;
    hal_s32_t block_key;
    hal_s32_t state_key;
    hal_s32_t stream_depth;
    hal_float_t max_feed_override;
    hal_float_t rate_reserve;
    hal_float_t brake_speed;
    AxisParams axis[firtp::max_axes];
};

int comp_id = -1;
Pins* pins = nullptr;
firtp::ComponentLogic* core = nullptr;
hal_stream_t block_stream;
hal_stream_t state_stream;
bool has_block_stream = false;
bool has_state_stream = false;
std::uint32_t state_overruns = 0;
std::uint32_t ticks = 0;
firtp::control_pins::Levels controls;  // the operator controls applied last, and their generation
std::uint32_t control_gen = 0;

namespace pin = firtp::hal_pin;  // pins are shared with other threads (hal_pin_access.hpp)

bool read_block(void*, firtp::stream::BlockRecord& record) {
    hal_stream_data buffer[firtp::stream::block_elements];
    if (hal_stream_read(&block_stream, buffer, nullptr) != 0) return false;
    firtp::stream::unpack(buffer, record);
    return true;
}

// One servo period.
void update(void*, long) {
    firtp::ComponentInputs in;
    in.enable = pin::get(pins->enable);
    // The controls as one whole generation of the bridge's, or the last one while it writes the next
    // (control_pins.hpp): the progress record below names the generation applied in this period.
    firtp::control_pins::read({pins->control_gen, pins->feed_scale, pins->hold, pins->abort}, controls, control_gen);
    in.feed_scale = controls.feed_scale;
    in.hold = controls.hold;
    in.abort = controls.abort;
    in.strobe = pin::get(pins->block_strobe);
    for (int a = 0; a < firtp::max_axes; ++a) in.pin_block.block.target[a] = pin::get(pins->block_target[a]);
    in.pin_block.block.feed = pin::get(pins->block_feed);
    in.pin_block.block.tolerance = pin::get(pins->block_tolerance);
    in.pin_block.block.termination =
        pin::get(pins->block_exact_stop) ? firtp::Termination::exact_stop : firtp::Termination::blend;
    in.pin_block.block.line = pin::get(pins->block_line);
    in.pin_block.program = pin::get(pins->block_program);
    in.pin_block.seq = pin::get(pins->block_seq);
    in.pin_motion_type = pin::get(pins->block_motion_type);
    in.events.tool_changed = pin::get(pins->tool_changed);
    in.events.resume = pin::get(pins->resume);
    in.events.optional_stop = pin::get(pins->optional_stop);
    for (int a = 0; a < axes; ++a) {
        in.position_feedback[a] = pin::get(pins->axis[a].pos_fb);
        in.velocity_feedback[a] = pin::get(pins->axis[a].vel_fb);
    }

    firtp::ComponentOutputs out;
    core->update(in, {has_block_stream ? read_block : nullptr, nullptr}, out);

    for (int a = 0; a < axes; ++a) {
        pin::set(pins->axis[a].pos_cmd, out.state.position[a]);
        pin::set(pins->axis[a].vel_cmd, out.state.velocity[a]);
        pin::set(pins->axis[a].acc_cmd, out.state.acceleration[a]);
    }
    pin::set(pins->block_ack, out.ack);
    pin::set(pins->busy, out.busy);
    pin::set(pins->done, out.done);
    pin::set(pins->queue_depth, out.queue_depth);
    pin::set(pins->queue_free, out.queue_free);
    pin::set(pins->current_line, static_cast<std::int32_t>(out.state.line));
    pin::set(pins->state, static_cast<std::int32_t>(out.mode));
    pin::set(pins->error_code, static_cast<std::int32_t>(out.error));
    pin::set(pins->program, static_cast<std::uint32_t>(out.program));  // low 32 bits
    pin::set(pins->next_seq, static_cast<std::uint32_t>(out.next_seq));
    pin::set(pins->rejected, out.rejected);
    const firtp::EventOutputs& e = out.events;
    pin::set(pins->spindle_on, e.spindle_on);
    pin::set(pins->spindle_forward, e.spindle_forward);
    pin::set(pins->spindle_reverse, e.spindle_reverse);
    pin::set(pins->spindle_speed_out, e.spindle_speed);
    pin::set(pins->coolant_flood, e.coolant_flood);
    pin::set(pins->coolant_mist, e.coolant_mist);
    pin::set(pins->tool_prep_number, e.tool_prep_number);
    pin::set(pins->tool_number, e.tool_number);
    pin::set(pins->tool_change, e.tool_change);
    pin::set(pins->paused, e.paused);
    pin::set(pins->program_end, e.program_end);
    pin::set(pins->events, e.events);
    if (has_state_stream) {
        hal_stream_data record[firtp::stream::state_elements];
        bool lost = false;  // a period's records go whole or not at all: one axis state lost
        for (int g = 0; g < firtp::stream::groups_for(axes) && !lost; ++g) {
            firtp::stream::pack_state(out.state, ticks, g, axes, record);
            lost = hal_stream_write(&state_stream, record) != 0;
        }
        if (!lost) {
            firtp::stream::pack_progress({out.program, out.next_seq, control_gen}, ticks, static_cast<std::int32_t>(out.state.line),
                                         axes, record);
            lost = hal_stream_write(&state_stream, record) != 0;
        }
        if (lost) ++state_overruns;
    }
    ticks = ticks + 1;
    pin::set(pins->tick, ticks);
    pin::set(pins->state_overruns, state_overruns);
}

// Module parameters are checked at load, and a bad one refuses the load naming it (init only:
// these throw std::invalid_argument, caught in rtapi_app_main).
[[noreturn]] void refuse(const char* name, const char* text, const std::string& why) {
    throw std::invalid_argument(std::string(name) + (text && *text ? std::string("=") + text : std::string()) + ": " + why);
}

// A number parameter: absent or empty gives `fallback`; otherwise a whole finite number.
double number(const char* name, const char* text, double fallback) {
    if (text == nullptr || *text == '\0') return fallback;
    const std::optional<double> value = firtp::module_number(text);
    if (!value) refuse(name, text, "not a finite number");
    return *value;
}

// "a,b,c" into field `limit` of the first axes: each a finite number >= 0 (0: not limited).
void read_limits(const char* name, const char* text, double firtp::AxisLimits::*limit, firtp::MachineLimits& limits) {
    if (text == nullptr || *text == '\0') return;
    const std::string list = text;
    std::size_t begin = 0;
    for (int a = 0;; ++a) {
        const std::size_t comma = std::min(list.find(',', begin), list.size());
        if (a >= axes) refuse(name, text, "more values than axes=" + std::to_string(axes));
        const std::string item = list.substr(begin, comma - begin);
        const std::optional<double> value = firtp::module_number(item.c_str());
        if (!value) refuse(name, text, "'" + item + "' is not a finite number");
        if (*value < 0.0) refuse(name, text, "'" + item + "' must be zero (no limit) or positive");
        limits.axis[a].*limit = *value;
        if (comma == list.size()) break;
        begin = comma + 1;
    }
}

int make_pins() {
    int r = 0;
#define FIRTP_AXIS_PIN(member, name, type, direction, doc) \
    r = r ? r : hal_pin_##type##_newf(HAL_##direction, &pins->axis[a].member, comp_id, "firtp." name, a);
    for (int a = 0; a < axes && r == 0; ++a) {
        FIRTP_AXIS_PINS(FIRTP_AXIS_PIN)
    }
#undef FIRTP_AXIS_PIN
#define FIRTP_TARGET_PIN(member, name, type, direction, doc)                                          \
    if (a < axes) r = hal_pin_##type##_newf(HAL_##direction, &pins->member[a], comp_id, "firtp." name, a); \
    else pins->member[a] = static_cast<hal_##type##_t*>(hal_malloc(sizeof(hal_##type##_t)));
    for (int a = 0; a < firtp::max_axes && r == 0; ++a) {  // unused axes keep their storage, set to 0
        FIRTP_TARGET_PINS(FIRTP_TARGET_PIN)
    }
#undef FIRTP_TARGET_PIN
#define FIRTP_PIN(member, name, type, direction, doc) \
    r = r ? r : hal_pin_##type##_newf(HAL_##direction, &pins->member, comp_id, "firtp." name);
    FIRTP_PINS(FIRTP_PIN)
#undef FIRTP_PIN
    if (r == 0) {
        *pins->feed_scale = 1.0;
        *pins->control_gen = 0;  // unconnected: the levels are taken every period
        *pins->block_motion_type = 2;
        *pins->next_seq = 1;
    }
    return r;
}

int make_params(const firtp::ComponentSettings& s) {
    auto* p = static_cast<Params*>(hal_malloc(sizeof(Params)));
    if (p == nullptr) return -ENOMEM;
    const firtp::PlannerParameters& planner = s.planner;
    p->axes = s.axes;
    p->fixed_chain = planner.fixed_chain;
    p->stages = planner.fixed_chain ? planner.filters.stages : 0;
    for (int i = 0; i < firtp::max_stages; ++i) p->t[i] = planner.fixed_chain && i < planner.filters.stages ? planner.filters.T[i] : 0.0;
    p->tolerance = s.default_tolerance;
    p->contour = planner.tolerance_meaning == firtp::ToleranceMeaning::contour;
    p->period_ns = static_cast<rtapi_s32>(period_ns);
    p->queue = static_cast<rtapi_s32>(planner.queue_capacity);
    p->max_blocks = s.max_blocks_per_period;
    p->plan_budget_us = plan_budget_us;
    p->block_key = static_cast<rtapi_s32>(block_key);
    p->state_key = static_cast<rtapi_s32>(state_key);
    p->stream_depth = stream_depth;
    p->max_feed_override = planner.max_rate;
    p->rate_reserve = planner.rate_reserve;
    p->brake_speed = s.brake_speed;
    int r = 0;
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->axes, comp_id, "firtp.axes");
    r = r ? r : hal_param_bit_newf(HAL_RO, &p->fixed_chain, comp_id, "firtp.fixed-chain");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->stages, comp_id, "firtp.stages");
    for (int i = 0; i < firtp::max_stages && r == 0; ++i)
        r = hal_param_float_newf(HAL_RO, &p->t[i], comp_id, "firtp.t%d", i + 1);
    r = r ? r : hal_param_float_newf(HAL_RO, &p->tolerance, comp_id, "firtp.tolerance");
    r = r ? r : hal_param_bit_newf(HAL_RO, &p->contour, comp_id, "firtp.contour");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->period_ns, comp_id, "firtp.period-ns");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->queue, comp_id, "firtp.queue");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->max_blocks, comp_id, "firtp.max-blocks");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->plan_budget_us, comp_id, "firtp.plan-budget-us");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->block_key, comp_id, "firtp.block-key");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->state_key, comp_id, "firtp.state-key");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->stream_depth, comp_id, "firtp.stream-depth");
    r = r ? r : hal_param_float_newf(HAL_RO, &p->max_feed_override, comp_id, "firtp.max-feed-override");
    r = r ? r : hal_param_float_newf(HAL_RO, &p->rate_reserve, comp_id, "firtp.rate-reserve");
    r = r ? r : hal_param_float_newf(HAL_RO, &p->brake_speed, comp_id, "firtp.brake-speed");
    for (int a = 0; a < axes && r == 0; ++a) {
        const firtp::AxisLimits& limit = planner.limits.axis[a];
        p->axis[a].max_velocity = limit.max_velocity;
        p->axis[a].max_acceleration = limit.max_acceleration;
        p->axis[a].max_jerk = limit.max_jerk;
        r = r ? r : hal_param_float_newf(HAL_RO, &p->axis[a].max_velocity, comp_id, "firtp.axis.%d.max-velocity", a);
        r = r ? r : hal_param_float_newf(HAL_RO, &p->axis[a].max_acceleration, comp_id, "firtp.axis.%d.max-acceleration", a);
        r = r ? r : hal_param_float_newf(HAL_RO, &p->axis[a].max_jerk, comp_id, "firtp.axis.%d.max-jerk", a);
    }
    return r;
}

firtp::ComponentSettings settings_from_parameters() {
    firtp::ComponentSettings s;
    const std::string period_text = std::to_string(period_ns);
    if (period_ns <= 0) refuse("period_ns", period_text.c_str(), "must be positive");
    s.planner.period = static_cast<double>(period_ns) * 1e-9;
    s.planner.fixed_chain = t1 != nullptr && *t1 != '\0';
    if (s.planner.fixed_chain) {
        const std::string stages_text = std::to_string(stages);
        if (stages < 1 || stages > firtp::max_stages) refuse("stages", stages_text.c_str(), "must be 1 to 4");
        s.planner.filters.stages = stages;
        const char* names[] = {"t1", "t2", "t3", "t4"};
        const char* times[] = {t1, t2, t3, t4};
        for (int i = 0; i < firtp::max_stages; ++i) {
            s.planner.filters.T[i] = number(names[i], times[i], 0.0);
            if (i < stages && !(s.planner.filters.T[i] > 0.0))
                refuse(names[i], times[i], "stages=" + stages_text + " needs a positive time in seconds");
        }
        if (const char* why = firtp::validate(s.planner.filters); *why) refuse("t1..t4", "", why);
        if (const char* why = firtp::validate_window(s.planner.filters, s.planner.period); *why)
            refuse("t1..t4 and period_ns", period_text.c_str(), why);
    }
    if (meaning) s.planner.tolerance_meaning = *firtp::parse_tolerance_meaning(meaning);  // checked at load
    s.planner.limits.axes = axes;
    read_limits("max_velocity", max_velocity, &firtp::AxisLimits::max_velocity, s.planner.limits);
    read_limits("max_acceleration", max_acceleration, &firtp::AxisLimits::max_acceleration, s.planner.limits);
    read_limits("max_jerk", max_jerk, &firtp::AxisLimits::max_jerk, s.planner.limits);
    // An axis without an acceleration limit is one the machine does not have (a lathe's Y, from
    // [TRAJ]COORDINATES): blocks that move it are refused. At least one axis needs a limit.
    if (!s.planner.fixed_chain &&
        std::none_of(s.planner.limits.axis.begin(), s.planner.limits.axis.begin() + axes,
                     [](const firtp::AxisLimits& l) { return l.max_acceleration > 0.0; }))
        refuse("max_acceleration", max_acceleration, "needs a limit for the machine's axes (or give t1: the fixed chain)");
    s.axes = axes;
    if (queue < 2) refuse("queue", std::to_string(queue).c_str(), "must be at least 2");
    s.planner.queue_capacity = static_cast<std::size_t>(queue);
    if (max_blocks < 1) refuse("max_blocks", std::to_string(max_blocks).c_str(), "must be at least 1");
    s.max_blocks_per_period = max_blocks;
    if (plan_budget_us < 0) refuse("plan_budget_us", std::to_string(plan_budget_us).c_str(), "must be 0 (none) or positive");
    s.plan_budget_ns = static_cast<std::int64_t>(plan_budget_us) * 1000;
    if (stream_depth < 2) refuse("stream_depth", std::to_string(stream_depth).c_str(), "must be at least 2");
    s.clock_ns = [] { return static_cast<std::int64_t>(rtapi_get_time()); };
    s.default_tolerance = number("tolerance", tolerance, firtp::defaults::tolerance);
    if (!(s.default_tolerance > 0.0)) refuse("tolerance", tolerance, "must be positive");
    s.planner.max_rate = number("max_feed_override", max_feed_override, firtp::defaults::max_feed_override);
    if (!(s.planner.max_rate >= 1.0)) refuse("max_feed_override", max_feed_override, "must be at least 1 (100 %)");
    s.planner.rate_reserve = number("rate_reserve", rate_reserve, firtp::defaults::rate_reserve);
    if (!(s.planner.rate_reserve > 0.0 && s.planner.rate_reserve < 1.0))
        refuse("rate_reserve", rate_reserve, "must lie between 0 and 1 (a share of the acceleration and jerk limits)");
    s.brake_speed = number("brake_speed", brake_speed, 1.0);
    if (!(s.brake_speed >= 0.0)) refuse("brake_speed", brake_speed, "must be zero or positive, units/s");
    return s;
}

int fail(const char* what) {
    rtapi_print_msg(RTAPI_MSG_ERR, "firtp: %s\n", what);
    if (comp_id >= 0) hal_exit(comp_id);
    comp_id = -1;
    return -EINVAL;
}

}  // namespace

extern "C" int rtapi_app_main(void) {
    // firtp.so may stay mapped after an unload (unique C++ symbols): a reload starts these afresh.
    has_block_stream = has_state_stream = false;
    state_overruns = ticks = control_gen = 0;
    controls = {};
    comp_id = hal_init("firtp");
    if (comp_id < 0) return comp_id;
    if (axes < 1 || axes > firtp::max_axes) return fail(("axes=" + std::to_string(axes) + ": must be 1 to 9").c_str());
    if (meaning && !firtp::parse_tolerance_meaning(meaning))
        return fail((std::string("meaning=") + meaning + ": must be corner or contour").c_str());
    firtp::ComponentSettings settings;
    try {
        settings = settings_from_parameters();
        core = new firtp::ComponentLogic(settings);  // init only, never in the servo thread
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    pins = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
    if (!pins || make_pins() != 0) return fail("cannot create pins");
    if (make_params(settings) != 0) return fail("cannot create params");
    if (block_key != 0) {
        if (hal_stream_create(&block_stream, comp_id, static_cast<int>(block_key), stream_depth,
                              firtp::stream::block_types) != 0)
            return fail("cannot create the block stream");
        has_block_stream = true;
    }
    if (state_key != 0) {
        if (hal_stream_create(&state_stream, comp_id, static_cast<int>(state_key),
                              stream_depth * firtp::stream::records_per_period(axes), firtp::stream::state_types) != 0)
            return fail("cannot create the axis-state stream");
        has_state_stream = true;
    }
    if (hal_export_funct("firtp.update", update, nullptr, 1, 0, comp_id) != 0) return fail("cannot export firtp.update");
    hal_ready(comp_id);
    return 0;
}

extern "C" void rtapi_app_exit(void) {
    if (has_block_stream) hal_stream_destroy(&block_stream);
    if (has_state_stream) hal_stream_destroy(&state_stream);
    has_block_stream = has_state_stream = false;
    delete core;
    core = nullptr;
    if (comp_id >= 0) hal_exit(comp_id);
}
