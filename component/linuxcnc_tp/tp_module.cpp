// firtp_tp: LinuxCNC 2.9's trajectory-planner module (tp.h, the 29 tp* functions motmod resolves
// and tcqFull) on firtp. Load it with [TRAJ]TPMOD = firtp_tp or `linuxcnc -t "firtp_tp ..."`;
// motmod then binds its tp* references to these definitions (rtapi_app opens modules RTLD_GLOBAL).
//
//   loadrt firtp_tp [t1=S] [t2=S] [t3=S t4=S stages=N] [jerk=J] [tolerance=T] [chord_tol=C]
//                   [meaning=corner|contour] [rate_reserve=R] [queue=MOVES] [blocks=BLOCKS] [max_blocks=N]
//                   [plan_budget_us=US] [arena_mb=MB]
//
// Every tp* call maps onto firtp::linuxcnc_tp::TpCore (tp_core.hpp says how); this file only
// translates LinuxCNC's types, reads the inputs motmod leaves in emcmotStatus/emcmotConfig, writes
// the status fields the stock planner writes, and reports refusals with rtapi_print_msg. State is
// module-static: motmod's TP_STRUCT has a frozen layout, only reverse_run and the copies of the
// position and status are kept in it.
//
// The jerk limit: jerk= if given (every axis), else the INI's [TRAJ]MAX_LINEAR_JERK and
// [AXIS_L]MAX_JERK per axis as LinuxCNC master's jerk-limited planner reads them (an axis without
// one: the smallest given), else 100000. The INI is the one the `linuxcnc` launcher exports as INI_FILE_NAME, which
// rtapi_app inherits; it is read here at load only (tp_ini.hpp).
//
// Load-time settings, as in effect, are read-only params: halcmd show param firtp_tp (man 9 firtp_tp).
//
// HAL (component firtp_tp, for measurement): pins firtp_tp.cycle-ns (tpRunCycle's time),
// firtp_tp.plan-ns (the planning part), firtp_tp.planned (blocks planned this period),
// firtp_tp.add-ns (the last tpAdd*), firtp_tp.adds (tpAdd* calls so far), firtp_tp.pending (moves not yet planned), firtp_tp.blocks
// (blocks in the planner), firtp_tp.depth, firtp_tp.rebuilds, firtp_tp.arena-kb.
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "posemath.h"  // its C++ part stays outside the extern "C" below
extern "C" {
// No linkage guards of their own: tcqFull and the tp* functions are C symbols, as in tpmod.
#include "tcq.h"
#include "tp_types.h"
}
#include "motion.h"    // emcmot_status_t, emcmot_config_t (tp.h needs them)
extern "C" {
#include "tp.h"
}

#include "tp_arena.hpp"
#include "tp_core.hpp"
#include "tp_ini.hpp"
#include <firtp/hal/module_number.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <optional>

MODULE_AUTHOR("firtp");
MODULE_DESCRIPTION("firtp: FIR-filter corner smoothing (Sencer et al. 2015) as LinuxCNC's trajectory planner");
MODULE_LICENSE("GPL");

// Module parameters (RTAPI has no double parameters: numbers are strings).
static char* t1 = nullptr;
RTAPI_MP_STRING(t1, "T1 in s, the longest filter (default: max over the axes of MAX_VELOCITY / MAX_ACCELERATION)");
static char* t2 = nullptr;
RTAPI_MP_STRING(t2, "T2 in s (default: max over the axes of MAX_ACCELERATION / jerk)");
static char* t3 = nullptr;
RTAPI_MP_STRING(t3, "T3 in s (stages=3 or 4)");
static char* t4 = nullptr;
RTAPI_MP_STRING(t4, "T4 in s (stages=4)");
static int stages = 2;
RTAPI_MP_INT(stages, "FIR stages, 1..4 (2)");
static char* jerk = nullptr;
RTAPI_MP_STRING(jerk, "jerk limit of every axis, machine units/s^3 (0: none); overrides the INI's [TRAJ]MAX_LINEAR_JERK "
                      "and [AXIS_L]MAX_JERK (per axis; without them 100000)");
static char* tolerance = nullptr;
RTAPI_MP_STRING(tolerance, "tolerance for G64 without P (and inside arcs in G61), machine units (" FIRTP_DEFAULT_TOLERANCE_TEXT ")");
static char* chord_tol = nullptr;
RTAPI_MP_STRING(chord_tol, "largest sagitta of an arc's chords, machine units (" FIRTP_DEFAULT_ARC_CHORD_TOLERANCE_TEXT ")");
static char* rate_reserve = nullptr;
RTAPI_MP_STRING(rate_reserve, "share of acceleration and jerk kept for feed override, hold and abort ramps (" FIRTP_DEFAULT_RATE_RESERVE_TEXT ")");
static char* meaning = nullptr;
RTAPI_MP_STRING(meaning, "what a tolerance bounds: corner (closest approach to the corner point, default) or contour");
static int queue = firtp::defaults::queue;
RTAPI_MP_INT(queue, "moves accepted and not finished, at most (" FIRTP_DEFAULT_QUEUE_TEXT "; tcqFull 16 before)");
static int blocks = firtp::defaults::tp_blocks;
RTAPI_MP_INT(blocks, "planned blocks (arc chords count one each) not yet finished, at most (" FIRTP_TP_DEFAULT_BLOCKS_TEXT ")");
static int max_blocks = firtp::defaults::tp_max_blocks;
RTAPI_MP_INT(max_blocks, "blocks planned per period at most (" FIRTP_TP_DEFAULT_MAX_BLOCKS_TEXT ")");
static int plan_budget_us = firtp::defaults::plan_budget_us;
RTAPI_MP_INT(plan_budget_us, "planning time per period after the first block, us (" FIRTP_DEFAULT_PLAN_BUDGET_US_TEXT "; 0: max_blocks only)");
static int arena_mb = 64;
RTAPI_MP_INT(arena_mb, "memory reserved at load for the planner, MB (64: 4096 blocks take about 52)");

namespace {

using firtp::linuxcnc_tp::AddStatus;
using firtp::linuxcnc_tp::Pose;
using firtp::linuxcnc_tp::TpCore;

struct Pins {
    hal_s32_t* cycle_ns;
    hal_s32_t* plan_ns;
    hal_s32_t* planned;
    hal_s32_t* add_ns;
    hal_s32_t* adds;
    hal_s32_t* pending;
    hal_s32_t* blocks;
    hal_s32_t* depth;
    hal_s32_t* rebuilds;
    hal_s32_t* arena_kb;
};

// Where the jerk limit came from (param firtp_tp.jerk-source).
enum JerkSource : int { jerk_default = 0, jerk_parameter = 1, jerk_ini = 2 };

// The load-time settings as read-only HAL params.
struct Params {
    hal_float_t jerk;
    hal_s32_t jerk_source;
    hal_float_t axis_jerk[firtp::linuxcnc_tp::pose_axes];  // X..W as applied
    hal_s32_t stages;
    hal_float_t t[4];  // as given; 0: from the axis limits (or no fixed chain)
    hal_float_t tolerance;
    hal_float_t chord_tol;
    hal_float_t rate_reserve;
    hal_bit_t contour;
    hal_s32_t queue;
    hal_s32_t blocks;
    hal_s32_t max_blocks;
    hal_s32_t plan_budget_us;
    hal_s32_t arena_mb;
    hal_float_t task_cycle;  // [TASK]CYCLE_TIME, s (0: unknown): a start waits at most 3 of them for more moves
};

int comp_id = -1;
Pins* pins = nullptr;
TpCore* core = nullptr;
emcmot_status_t* status = nullptr;
emcmot_config_t* config = nullptr;
void (*dio_write)(int, char) = nullptr;
void (*aio_write)(int, double) = nullptr;
double (*axis_vel_limit)(int) = nullptr;
double (*axis_acc_limit)(int) = nullptr;
bool reverse_refused_reported = false;
std::int64_t windows_reported = 0;  // TpCore's refused_windows already reported

std::int64_t now_ns() { return static_cast<std::int64_t>(rtapi_get_time()); }

// Absent or empty: `fallback`; not a whole finite number: NaN (refused below, naming the parameter).
double number(const char* text, double fallback) {
    if (text == nullptr || *text == '\0') return fallback;
    return firtp::module_number(text).value_or(NAN);
}

Pose pose_of(const EmcPose& p) {
    return {p.tran.x, p.tran.y, p.tran.z, p.a, p.b, p.c, p.u, p.v, p.w};
}

EmcPose emc_pose(const Pose& p) {
    EmcPose e;
    e.tran.x = p[0], e.tran.y = p[1], e.tran.z = p[2];
    e.a = p[3], e.b = p[4], e.c = p[5];
    e.u = p[6], e.v = p[7], e.w = p[8];
    return e;
}

void set_s32(hal_s32_t* pin, long long value) {
    if (pin != nullptr) *pin = static_cast<rtapi_s32>(value > 0x7fffffff ? 0x7fffffff : value);
}

void count_add(std::int64_t begin) {
    if (pins == nullptr) return;
    set_s32(pins->add_ns, now_ns() - begin);
    *pins->adds = static_cast<rtapi_s32>((*pins->adds + 1) & 0x7fffffff);
}

// Each refused change of the limits or period once: the planner is not rebuilt (no allocation).
void report_refused_window() {
    const std::int64_t refused = core->stats().refused_windows;
    if (refused == windows_reported) return;
    windows_reported = refused;
    rtapi_print_msg(RTAPI_MSG_ERR,
                    "firtp_tp: filter delay %g s refused: %s; the planner built before is kept and moves are refused "
                    "until this changes\n",
                    core->filter_delay(), firtp::linuxcnc_tp::describe(AddStatus::window_too_long));
}

// The axis limits as motmod has them now ([AXIS_n]MAX_VELOCITY, MAX_ACCELERATION, sent by task).
void refresh_limits() {
    if (axis_vel_limit == nullptr || axis_acc_limit == nullptr) return;
    Pose v{}, a{};
    for (int i = 0; i < 9; ++i) {
        v[i] = axis_vel_limit(i);
        a[i] = axis_acc_limit(i);
    }
    core->set_axis_limits(v, a);
    report_refused_window();
}

void write_digital(int index, char on) {
    if (dio_write != nullptr && config != nullptr && index < config->numDIO) dio_write(index, on);
}
void write_analog(int index, double value) {
    if (aio_write != nullptr && config != nullptr && index < config->numAIO) aio_write(index, value);
}

// Status fields the stock planner writes, from TpCore's state.
void publish(TP_STRUCT* tp) {
    tp->currentPos = emc_pose(core->position());
    tp->done = core->done() ? 1 : 0;
    tp->depth = core->depth();
    tp->activeDepth = core->active_depth();
    tp->execId = core->exec_id();
    tp->motionType = core->motion_type();
    tp->aborting = core->aborting() ? 1 : 0;
    tp->reverse_run = 0;
    if (tp->done) tp->goalPos = tp->currentPos;
    if (status == nullptr) return;
    status->current_vel = core->current_vel();
    status->requested_vel = core->requested_vel();
    status->distance_to_go = core->distance_to_go();
    status->dtg = emc_pose(core->dtg());
    status->enables_queued = core->has_exec() ? core->exec_enables() : status->enables_new;
    status->spindleSync = 0;
    status->tcqlen = static_cast<unsigned int>(core->depth());
}

int refused(AddStatus why, int id, const char* what) {
    if (why == AddStatus::ok || why == AddStatus::zero_length) return static_cast<int>(why);
    rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: %s at line %d refused: %s\n", what, id,
                    firtp::linuxcnc_tp::describe(why));
    return static_cast<int>(why);
}

firtp::linuxcnc_tp::MoveRequest request(const EmcPose& end, int type, double vel, double ini_maxvel, double acc,
                                        unsigned char enables, char atspeed, const state_tag_t& tag) {
    firtp::linuxcnc_tp::MoveRequest r;
    r.end = pose_of(end);
    r.motion_type = type;
    r.vel = vel;
    r.ini_maxvel = ini_maxvel;
    r.acc = acc;
    r.enables = enables;
    r.atspeed = atspeed != 0;
    r.tag = &tag;
    r.tag_size = sizeof tag;
    return r;
}

static_assert(sizeof(state_tag_t) <= firtp::linuxcnc_tp::tag_capacity, "TpCore keeps the state tag per move");

int fail(const char* what) {
    rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: %s\n", what);
    if (comp_id >= 0) hal_exit(comp_id);
    comp_id = -1;
    return -1;
}

int make_pins() {
    pins = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
    if (pins == nullptr) return -1;
    struct {
        hal_s32_t** pin;
        const char* name;
    } const list[] = {{&pins->cycle_ns, "cycle-ns"}, {&pins->plan_ns, "plan-ns"},   {&pins->planned, "planned"},
                      {&pins->add_ns, "add-ns"},     {&pins->adds, "adds"},         {&pins->pending, "pending"},
                      {&pins->blocks, "blocks"},     {&pins->depth, "depth"},       {&pins->rebuilds, "rebuilds"},
                      {&pins->arena_kb, "arena-kb"}};
    for (const auto& p : list) {
        if (hal_pin_s32_newf(HAL_OUT, p.pin, comp_id, "firtp_tp.%s", p.name) != 0) return -1;
        **p.pin = 0;
    }
    return 0;
}

int make_params(const firtp::linuxcnc_tp::TpSettings& s, JerkSource source) {
    auto* p = static_cast<Params*>(hal_malloc(sizeof(Params)));
    if (p == nullptr) return -1;
    p->jerk = s.jerk;
    p->jerk_source = source;
    for (std::size_t a = 0; a < s.axis_jerk.size(); ++a) p->axis_jerk[a] = s.jerk_of(a);
    p->stages = s.stages;
    for (std::size_t i = 0; i < 4; ++i) p->t[i] = s.filter_times[i];
    p->tolerance = s.default_tolerance;
    p->chord_tol = s.chord_tolerance;
    p->rate_reserve = s.rate_reserve;
    p->contour = s.tolerance_meaning == firtp::ToleranceMeaning::contour;
    p->queue = static_cast<rtapi_s32>(s.moves);
    p->blocks = static_cast<rtapi_s32>(s.blocks);
    p->max_blocks = s.max_blocks_per_cycle;
    p->plan_budget_us = plan_budget_us;
    p->arena_mb = arena_mb;
    p->task_cycle = s.task_cycle;
    int r = 0;
    r = r ? r : hal_param_float_newf(HAL_RO, &p->jerk, comp_id, "firtp_tp.jerk");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->jerk_source, comp_id, "firtp_tp.jerk-source");
    for (int a = 0; a < firtp::linuxcnc_tp::pose_axes && r == 0; ++a)
        r = hal_param_float_newf(HAL_RO, &p->axis_jerk[a], comp_id, "firtp_tp.jerk-%c", "xyzabcuvw"[a]);
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->stages, comp_id, "firtp_tp.stages");
    for (int i = 0; i < 4 && r == 0; ++i) r = hal_param_float_newf(HAL_RO, &p->t[i], comp_id, "firtp_tp.t%d", i + 1);
    r = r ? r : hal_param_float_newf(HAL_RO, &p->tolerance, comp_id, "firtp_tp.tolerance");
    r = r ? r : hal_param_float_newf(HAL_RO, &p->chord_tol, comp_id, "firtp_tp.chord-tol");
    r = r ? r : hal_param_float_newf(HAL_RO, &p->rate_reserve, comp_id, "firtp_tp.rate-reserve");
    r = r ? r : hal_param_bit_newf(HAL_RO, &p->contour, comp_id, "firtp_tp.contour");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->queue, comp_id, "firtp_tp.queue");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->blocks, comp_id, "firtp_tp.blocks");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->max_blocks, comp_id, "firtp_tp.max-blocks");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->plan_budget_us, comp_id, "firtp_tp.plan-budget-us");
    r = r ? r : hal_param_s32_newf(HAL_RO, &p->arena_mb, comp_id, "firtp_tp.arena-mb");
    r = r ? r : hal_param_float_newf(HAL_RO, &p->task_cycle, comp_id, "firtp_tp.task-cycle");
    return r;
}

// jerk=, else the jerk keys of `ini` (nullptr: none), else TpSettings' default; false (reported)
// on a bad value.
bool choose_jerk(firtp::linuxcnc_tp::TpSettings& s, JerkSource& source, const char* ini) {
    if (jerk != nullptr && *jerk != '\0') {
        s.jerk = number(jerk, s.jerk);
        source = jerk_parameter;
        if (std::isnan(s.jerk) || s.jerk < 0.0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: jerk=%s: must be a number >= 0\n", jerk);
            return false;
        }
        return true;
    }
    source = jerk_default;
    if (ini == nullptr) return true;
    const firtp::linuxcnc_tp::IniJerk found = firtp::linuxcnc_tp::read_ini_jerk(ini);
    if (!found.error.empty()) {
        rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: jerk limit: %s\n", found.error.c_str());
        return false;
    }
    if (found.jerk == 0.0) return true;
    s.jerk = found.jerk;
    s.axis_jerk = found.axis;
    source = jerk_ini;
    rtapi_print_msg(RTAPI_MSG_INFO, "firtp_tp: jerk per axis from %s (the smallest %g, %s)\n", ini, s.jerk, found.from.c_str());
    return true;
}

}  // namespace

// ---- tp.h ----------------------------------------------------------------------------------

void tpMotFunctions(void (*pDioWrite)(int, char), void (*pAioWrite)(int, double), void (*)(int, int),
                    int (*)(int), double (*paxis_get_vel_limit)(int), double (*paxis_get_acc_limit)(int)) {
    dio_write = pDioWrite;
    aio_write = pAioWrite;
    axis_vel_limit = paxis_get_vel_limit;
    axis_acc_limit = paxis_get_acc_limit;
}

void tpMotData(emcmot_status_t* pstatus, emcmot_config_t* pconfig) {
    status = pstatus;
    config = pconfig;
}

int tpCreate(TP_STRUCT* const tp, int queueSize, int) {
    if (tp == nullptr || core == nullptr) return -1;
    std::memset(static_cast<void*>(tp), 0, sizeof *tp);
    tp->queueSize = queueSize;
    tp->cycleTime = core->settings().period;
    tp->done = 1;
    tp->termCond = TC_TERM_COND_PARABOLIC;
    tp->reverse_run = TC_DIR_FORWARD;
    tp->spindle.waiting_for_index = MOTION_INVALID_ID;
    tp->spindle.waiting_for_atspeed = MOTION_INVALID_ID;
    core->set_output_writers({write_digital, write_analog});
    return 0;
}

int tpClear(TP_STRUCT* const tp) {
    core->clear();
    publish(tp);
    tp->goalPos = tp->currentPos;
    tp->nextId = 0;
    tp->execId = 0;
    tp->pausing = 0;
    if (status != nullptr) {
        status->current_vel = 0.0;
        status->requested_vel = 0.0;
        status->distance_to_go = 0.0;
        ZERO_EMC_POSE(status->dtg);
        status->motionFlag |= EMCMOT_MOTION_INPOS_BIT;
    }
    return 0;
}

int tpSetCycleTime(TP_STRUCT* tp, double secs) {
    if (!core->set_period(secs)) return -1;
    report_refused_window();
    tp->cycleTime = secs;
    return 0;
}

int tpSetVmax(TP_STRUCT* tp, double vmax, double ini_maxvel) {
    if (!(vmax > 0.0) || !(ini_maxvel > 0.0)) return -1;
    tp->vMax = vmax;
    tp->ini_maxvel = ini_maxvel;
    return 0;
}

int tpSetVlimit(TP_STRUCT* tp, double limit) {
    tp->vLimit = limit > 0.0 ? limit : 0.0;
    core->set_velocity_limit(tp->vLimit);
    return 0;
}

int tpSetAmax(TP_STRUCT* tp, double amax) {
    if (!(amax > 0.0)) return -1;
    tp->aMax = amax;
    return 0;
}

int tpSetId(TP_STRUCT* tp, int id) {
    if (!MOTION_ID_VALID(id)) {
        rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: invalid motion id %d\n", id);
        return -1;
    }
    tp->nextId = id;
    core->set_id(id);
    return 0;
}

int tpGetExecId(TP_STRUCT*) { return core->exec_id(); }

struct state_tag_t tpGetExecTag(TP_STRUCT* const) {
    state_tag_t tag;
    std::memset(static_cast<void*>(&tag), 0, sizeof tag);
    if (const void* t = core->exec_tag()) std::memcpy(static_cast<void*>(&tag), t, sizeof tag);
    return tag;
}

int tpSetTermCond(TP_STRUCT* tp, int cond, double tol) {
    if (!core->set_term_cond(cond, tol)) return -1;
    tp->termCond = cond;
    tp->tolerance = tol;
    return 0;
}

int tpSetPos(TP_STRUCT* tp, EmcPose const* const pos) {
    if (pos == nullptr) return -1;
    const Pose p = pose_of(*pos);
    for (double v : p)
        if (!std::isfinite(v)) return -1;
    core->set_position(p);
    publish(tp);
    tp->goalPos = *pos;
    return 0;
}

int tpRunCycle(TP_STRUCT* tp, long) {
    const std::int64_t begin = now_ns();
    firtp::linuxcnc_tp::CycleInputs in;
    if (status != nullptr) {
        in.feed_scale = status->net_feed_scale;
        const int spindles = config != nullptr ? config->numSpindles : 0;
        for (int s = 0; s < spindles && s < EMCMOT_MAX_SPINDLES; ++s)
            if (!status->spindle_status[s].at_speed) in.spindle_at_speed = false;
    }
    if (config != nullptr) in.max_feed_scale = config->maxFeedScale;
    if (core->done()) refresh_limits();  // changed limits rebuild the planner while idle
    core->run_cycle(in);
    publish(tp);
    if (pins != nullptr) {
        const firtp::linuxcnc_tp::CycleStats& s = core->stats();
        set_s32(pins->plan_ns, s.plan_ns);
        set_s32(pins->planned, s.planned);
        set_s32(pins->pending, static_cast<long long>(s.pending));
        set_s32(pins->blocks, static_cast<long long>(s.blocks));
        set_s32(pins->depth, core->depth());
        set_s32(pins->rebuilds, s.rebuilds);
        set_s32(pins->arena_kb, static_cast<long long>(tp_arena_used() / 1024));
        set_s32(pins->cycle_ns, now_ns() - begin);
    }
    return 0;
}

int tpPause(TP_STRUCT* tp) {
    core->pause();
    tp->pausing = 1;
    return 0;
}

int tpResume(TP_STRUCT* tp) {
    core->resume();
    tp->pausing = 0;
    return 0;
}

int tpAbort(TP_STRUCT* tp) {
    core->abort();
    tp->aborting = 1;
    return 0;
}

int tpAddRigidTap(TP_STRUCT* const tp, EmcPose, double, double, double, unsigned char, double, struct state_tag_t) {
    rtapi_print_msg(RTAPI_MSG_ERR,
                    "firtp_tp: rigid tapping (G33.1, G84 with rigid tapping) at line %d refused: it needs spindle "
                    "position tracking, which firtp_tp does not do; use the stock tpmod\n",
                    tp->nextId);
    return -1;
}

int tpAddLine(TP_STRUCT* const tp, EmcPose end, int canon_motion_type, double vel, double ini_maxvel, double acc,
              unsigned char enables, char atspeed, int indexrotary, struct state_tag_t tag) {
    const std::int64_t begin = now_ns();
    refresh_limits();
    firtp::linuxcnc_tp::MoveRequest r = request(end, canon_motion_type, vel, ini_maxvel, acc, enables, atspeed, tag);
    r.indexer_joint = indexrotary;
    const int result = refused(core->add_line(r), tp->nextId, "linear move");
    if (result == 0) tp->goalPos = end;
    count_add(begin);
    return result;
}

int tpAddCircle(TP_STRUCT* const tp, EmcPose end, PmCartesian center, PmCartesian normal, int turn,
                int canon_motion_type, double vel, double ini_maxvel, double acc, unsigned char enables,
                char atspeed, struct state_tag_t tag) {
    const std::int64_t begin = now_ns();
    refresh_limits();
    const firtp::linuxcnc_tp::MoveRequest r =
        request(end, canon_motion_type, vel, ini_maxvel, acc, enables, atspeed, tag);
    const firtp::linuxcnc_tp::ArcGeometry arc{{center.x, center.y, center.z}, {normal.x, normal.y, normal.z}, turn};
    const int result = refused(core->add_arc(r, arc), tp->nextId, "circular move");
    if (result == 0) tp->goalPos = end;
    count_add(begin);
    return result;
}

int tpGetPos(TP_STRUCT const* const tp, EmcPose* const pos) {
    *pos = tp->currentPos;
    return 0;
}

int tpIsDone(TP_STRUCT* const) { return core->done() ? 1 : 0; }
int tpQueueDepth(TP_STRUCT* const) { return core->depth(); }
int tpActiveDepth(TP_STRUCT* const) { return core->active_depth(); }
int tpGetMotionType(TP_STRUCT* const) { return core->motion_type(); }

int tpSetSpindleSync(TP_STRUCT* const tp, int spindle, double sync, int wait) {
    tp->synchronized = sync != 0.0;
    tp->uu_per_rev = sync;
    tp->velocity_mode = wait;
    tp->spindle.spindle_num = spindle;
    core->set_spindle_sync(sync);  // the next move is refused while this is not 0
    return 0;
}

int tpSetAout(TP_STRUCT* const, unsigned char index, double start, double) {
    if (!core->latch_analog(index, start)) {
        rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: analog output %d: too many outputs waiting for their move\n", index);
        return -1;
    }
    return 0;
}

int tpSetDout(TP_STRUCT* const, int index, unsigned char start, unsigned char) {
    if (!core->latch_digital(index, start != 0)) {
        rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: digital output %d: too many outputs waiting for their move\n", index);
        return -1;
    }
    return 0;
}

int tpSetRunDir(TP_STRUCT* const tp, tc_direction_t dir) {
    if (dir == TC_DIR_FORWARD) {
        tp->reverse_run = TC_DIR_FORWARD;
        return 0;
    }
    if (!reverse_refused_reported) {
        rtapi_print_msg(RTAPI_MSG_ERR, "firtp_tp: running backwards along the path (negative adaptive feed) is not "
                                       "supported; adaptive feed is held at 0 instead\n");
        reverse_refused_reported = true;
    }
    return -1;
}

int tcqFull(TC_QUEUE_STRUCT const* const) { return core == nullptr || core->full() ? 1 : 0; }

// ---- module ---------------------------------------------------------------------------------

extern "C" int rtapi_app_main(void) {
    comp_id = hal_init("firtp_tp");
    if (comp_id < 0) return comp_id;
    if (arena_mb < 1 || !tp_arena_reserve(static_cast<std::size_t>(arena_mb) << 20))
        return fail("cannot reserve the memory arena (arena_mb)");
    firtp::linuxcnc_tp::TpSettings s;
    s.stages = stages;
    const char* times[4] = {t1, t2, t3, t4};
    for (std::size_t i = 0; i < 4; ++i) s.filter_times[i] = number(times[i], 0.0);
    s.default_tolerance = number(tolerance, firtp::defaults::tolerance);
    s.chord_tolerance = number(chord_tol, firtp::defaults::arc_chord_tolerance);
    s.rate_reserve = number(rate_reserve, firtp::defaults::rate_reserve);
    const std::optional<firtp::ToleranceMeaning> given_meaning =
        meaning != nullptr ? firtp::parse_tolerance_meaning(meaning) : s.tolerance_meaning;
    if (!given_meaning) return fail("meaning must be corner or contour");
    s.tolerance_meaning = *given_meaning;
    s.moves = queue > 0 ? static_cast<std::size_t>(queue) : 0;
    s.blocks = blocks > 0 ? static_cast<std::size_t>(blocks) : 0;
    s.max_blocks_per_cycle = max_blocks;
    s.plan_budget_ns = static_cast<std::int64_t>(plan_budget_us) * 1000;
    s.clock_ns = now_ns;
    for (double v : s.filter_times)
        if (std::isnan(v) || v < 0.0) return fail("t1..t4 must be numbers of seconds >= 0");
    JerkSource source = jerk_default;
    const char* ini = std::getenv("INI_FILE_NAME");  // the linuxcnc launcher's; unset under plain halrun
    if (ini != nullptr && *ini == '\0') ini = nullptr;
    if (!choose_jerk(s, source, ini)) return fail("not loaded: the jerk limit");
    if (ini != nullptr) s.task_cycle = firtp::linuxcnc_tp::read_ini_task_cycle(ini);
    try {
        core = new TpCore(s);  // at load, never in the servo thread
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    if (make_pins() != 0) return fail("cannot create the firtp_tp.* pins");
    if (make_params(s, source) != 0) return fail("cannot create the firtp_tp.* params");
    rtapi_print_msg(RTAPI_MSG_INFO,
                    "firtp_tp: %d stages, t1=%s t2=%s (0: from the axis limits), tolerance %g, jerk %g, task cycle %g s\n",
                    stages, t1 ? t1 : "0", t2 ? t2 : "0", s.default_tolerance, s.jerk, s.task_cycle);
    hal_ready(comp_id);
    return 0;
}

extern "C" void rtapi_app_exit(void) {
    delete core;
    core = nullptr;
    if (comp_id >= 0) hal_exit(comp_id);
}
