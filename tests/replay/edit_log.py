#!/usr/bin/env python3
"""Writes a damaged copy of an LCM log (lcm-logger's format), for tests of firtp record / replay:
   edit_log.py IN OUT drop CHANNEL EVERY   drop every EVERY-th event on CHANNEL (the 2nd, ...)
   edit_log.py IN OUT dup CHANNEL EVERY    write every EVERY-th event on CHANNEL twice
   edit_log.py IN OUT flip CHANNEL INDEX   flip one bit in the INDEX-th event on CHANNEL (crc no longer matches)
   edit_log.py IN OUT strip CHANNEL        leave out every event on CHANNEL
   edit_log.py IN OUT nudge CHANNEL INDEX  change the lowest bit of position X in the INDEX-th axis state,
                                           crc recomputed (an intact message that says something else)
   edit_log.py IN OUT append LOG2         IN's events, then LOG2's: two runs of the component in one log
   edit_log.py IN OUT from CHANNEL INDEX   leave out everything before the INDEX-th event on CHANNEL but
                                           FIRTP_CONFIG (a recorder started late)
   edit_log.py IN OUT restart CHANNEL INDEX   the bridge started again before the INDEX-th axis state while the
                                           component ran on (CHANNEL: FIRTP_AXIS_STATE): from there the states' seq
                                           from 1 and the control they name 0, 0 until it changes, a FIRTP_CONFIG
                                           (seq 1, then on) before it
   edit_log.py IN OUT old CHANNEL          every axis state as firtp wrote it before control_session and
                                           control_seq: that type's fingerprint, without those 16 bytes, sealed
"""
import struct
import sys
import zlib

POSITION_X = 44  # axis_state_t: fingerprint, utime, seq, tick (8 bytes each), time (8), line (4)
AXIS_STATE_BEFORE_CONTROLS = bytes.fromhex("c4dee41eef8eeb16")  # its fingerprint then


def sealed(payload):
    """The message with its crc (last 4 bytes) recomputed: lcm-types/README.md, "Integrity"."""
    return payload[:-4] + struct.pack(">I", zlib.crc32(payload[:-4]))

SYNC = 0xEDA1DA01


def events(path):
    data = open(path, "rb").read()
    at = 0
    while at < len(data):
        sync, num, utime, clen, dlen = struct.unpack_from(">IqqII", data, at)
        assert sync == SYNC, f"{path}: bad sync word at byte {at}"
        at += 28
        channel = data[at:at + clen]
        at += clen
        payload = data[at:at + dlen]
        at += dlen
        yield utime, channel, payload


def main():
    src, dst, op, channel = sys.argv[1:5]
    arg = int(sys.argv[5]) if len(sys.argv) > 5 else 0
    out, seen = [], 0
    if op == "append":
        out = list(events(src)) + list(events(channel))
        src, channel = "/dev/null", ""
    started = op != "from"
    if op == "restart":
        out, configs, config, named, renamed = [], 0, None, None, True
        for utime, ch, payload in events(src):
            name = ch.decode()
            if name == "FIRTP_CONFIG":
                config = payload
                if seen >= arg:
                    configs += 1
                    payload = sealed(payload[:16] + struct.pack(">q", configs) + payload[24:])
            if name == channel:
                seen += 1
                if seen == arg - 1:
                    named = payload[-20:-4]
                if seen == arg:
                    configs = 1
                    out.append((utime, b"FIRTP_CONFIG", sealed(config[:16] + struct.pack(">q", 1) + config[24:])))
                if seen >= arg:
                    renamed = renamed and payload[-20:-4] == named
                    control = bytes(16) if renamed else payload[-20:-4]
                    payload = sealed(payload[:16] + struct.pack(">q", seen - arg + 1) + payload[24:-20] + control + payload[-4:])
            out.append((utime, ch, payload))
        src = "/dev/null"
    for utime, ch, payload in events(src):
        if op == "from" and ch.decode() == channel and seen + 1 == arg:
            started = True
        if not started and ch.decode() != "FIRTP_CONFIG":
            if ch.decode() == channel:
                seen += 1
            continue
        if ch.decode() != channel:
            out.append((utime, ch, payload))
            continue
        seen += 1
        if op == "strip" or (op == "drop" and seen % arg == 0):
            continue
        if op == "flip" and seen == arg:
            payload = payload[:20] + bytes([payload[20] ^ 1]) + payload[21:]
        if op == "old":  # control_session, control_seq: the 16 bytes before the crc
            payload = sealed(AXIS_STATE_BEFORE_CONTROLS + payload[8:-20] + payload[-4:])
        if op == "nudge" and seen == arg:
            at = POSITION_X + 7
            payload = sealed(payload[:at] + bytes([payload[at] ^ 1]) + payload[at + 1:])
        out.append((utime, ch, payload))
        if op == "dup" and seen % arg == 0:
            out.append((utime, ch, payload))
    with open(dst, "wb") as f:
        for num, (utime, ch, payload) in enumerate(out):
            f.write(struct.pack(">IqqII", SYNC, num, utime, len(ch), len(payload)) + ch + payload)


main()
