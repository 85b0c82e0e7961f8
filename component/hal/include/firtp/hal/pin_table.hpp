// The HAL pins of firtp.so, declared once: firtp.cpp makes its Pins struct and creates the pins
// from these lists, and firtp_pin_docs prints the pin tables of docs/GUIDE.md and docs/man/firtp.9
// from them (the test hal.pin_docs holds the documents to it).
//
// X(member, name, type, direction, doc): `name` follows "firtp."; `type` is float, bit, s32 or u32
// (hal_<type>_t, hal_pin_<type>_newf); `direction` IN or OUT (HAL_IN, HAL_OUT). Names with %d are
// made once per axis, N = 0 .. axes-1. Pins are created in list order. Free of hal.h.
#pragma once

// Per axis (struct AxisPins).
#define FIRTP_AXIS_PINS(X)                                                                                      \
    X(pos_cmd, "axis.%d.pos-cmd", float, OUT, "commanded position")                                           \
    X(vel_cmd, "axis.%d.vel-cmd", float, OUT, "commanded velocity")                                           \
    X(acc_cmd, "axis.%d.acc-cmd", float, OUT, "commanded acceleration")                                       \
    X(pos_fb, "axis.%d.pos-fb", float, IN,                                                                     \
      "where the axis is (encoder, stepgen feedback; in a simulation net pos-cmd to pos-fb): followed while "  \
      "disabled, and the start at the first period and when enable rises")                                    \
    X(vel_fb, "axis.%d.vel-fb", float, IN,                                                                     \
      "how fast the axis moves: above brake_speed at a start the component brakes from it within the limits")

// One block on pins, strobe/ack handshake (target per axis).
#define FIRTP_TARGET_PINS(X) X(block_target, "block.target.%d", float, IN, "end point of the pin block (absolute)")

#define FIRTP_PINS(X)                                                                                           \
    X(block_feed, "block.feed", float, IN, "path speed, units/s")                                              \
    X(block_tolerance, "block.tolerance", float, IN, "corner tolerance; 0: the module's tolerance")            \
    X(block_motion_type, "block.motion-type", s32, IN, "1 traverse, 2 feed")                                   \
    X(block_exact_stop, "block.exact-stop", bit, IN, "stop at the end of this block")                          \
    X(block_line, "block.line", s32, IN, "source line")                                                        \
    X(block_program, "block.program", u32, IN, "program id (with seq)")                                        \
    X(block_seq, "block.seq", u32, IN, "sequence number 1, 2, ... (0: not checked)")                           \
    X(block_strobe, "block.strobe", bit, IN, "raise when the block pins are set; lower after ack")             \
    X(block_ack, "block.ack", bit, OUT, "follows strobe once the block was taken")                             \
    X(busy, "busy", bit, OUT, "blocks queued or moving")                                                       \
    X(done, "done", bit, OUT, "nothing left to do")                                                            \
    X(queue_depth, "queue-depth", s32, OUT, "blocks not finished")                                             \
    X(queue_free, "queue-free", s32, OUT, "blocks that can still be taken")                                    \
    X(current_line, "current-line", s32, OUT, "line of the moving block")                                      \
    X(state, "state", s32, OUT, "0 idle, 1 moving, 2 holding, 3 aborting, 4 error, 5 disabled")                \
    X(error_code, "error-code", s32, OUT, "latest error, 0 none (the codes of firtp_lcm::status_t)")            \
    X(program, "program", u32, OUT, "program being accepted (low 32 bits)")                                    \
    X(next_seq, "next-seq", u32, OUT, "sequence number expected next")                                         \
    X(rejected, "rejected", u32, OUT, "records refused so far")                                                \
    X(tick, "tick", u32, OUT, "periods run")                                                                   \
    X(state_overruns, "state-overruns", u32, OUT, "axis states lost to a full stream")                          \
    X(enable, "enable", bit, IN, "off: stop at once, drop everything and follow pos-fb (drives off)")          \
    X(feed_scale, "feed-scale", float, IN, "feed override, 1 = as programmed")                                 \
    X(hold, "hold", bit, IN, "stop on the path and wait")                                                      \
    X(abort, "abort", bit, IN, "stop on the path and drop the program")                                        \
    X(control_gen, "control-gen", u32, IN,                                                                     \
      "from the LCM bridge: which operator control feed-scale, hold and abort hold (odd while it writes them: " \
      "they are taken at the next even value); unconnected: 0, the three are taken every period")              \
    FIRTP_EVENT_PINS(X)

// Program events (M3/M4/M5 S, M7/M8/M9, T M6, M0/M1, M2/M30) as motion reaches them; LinuxCNC's
// motion.spindle-* and iocontrol.0.* pins under firtp's names (docs/GUIDE.md, "Events").
#define FIRTP_EVENT_PINS(X)                                                                                     \
    X(spindle_on, "spindle-on", bit, OUT, "M3 or M4 reached, until M5")                                        \
    X(spindle_forward, "spindle-forward", bit, OUT, "M3: clockwise")                                           \
    X(spindle_reverse, "spindle-reverse", bit, OUT, "M4: counterclockwise")                                    \
    X(spindle_speed_out, "spindle-speed-out", float, OUT, "programmed spindle speed S, rpm (signed: M4 negative)") \
    X(coolant_flood, "coolant-flood", bit, OUT, "M8, until M9")                                                \
    X(coolant_mist, "coolant-mist", bit, OUT, "M7, until M9")                                                  \
    X(tool_prep_number, "tool-prep-number", s32, OUT, "T: the tool selected")                                  \
    X(tool_number, "tool-number", s32, OUT, "the tool in the spindle, after M6")                               \
    X(tool_change, "tool-change", bit, OUT, "M6 reached, at rest: change the tool, then set tool-changed")     \
    X(tool_changed, "tool-changed", bit, IN,                                                                   \
      "the tool is changed: motion goes on (net tool-change to it when nothing changes tools)")                \
    X(paused, "paused", bit, OUT, "M0 (or M1 with optional-stop) reached, at rest: waits for resume")          \
    X(resume, "resume", bit, IN, "a rising edge ends a pause")                                                 \
    X(optional_stop, "optional-stop", bit, IN, "M1 pauses only while this is set")                             \
    X(program_end, "program-end", bit, OUT, "M2 or M30 reached; cleared by the next program's first record")   \
    X(events, "events", u32, OUT, "program events reached so far")
