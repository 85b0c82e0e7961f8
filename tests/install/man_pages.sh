#!/usr/bin/env bash
# docs/man: each page renders with groff without a warning (-ww) and with man -l; firtp(9) names every
# module parameter, pin and param that component/hal/firtp.cpp creates, firtp_tp(9) those of
# component/linuxcnc_tp/tp_module.cpp, firtp(1) every firtp command and the exit codes.
set -euo pipefail
src=$1
command -v groff > /dev/null || { echo "SKIPPED: groff not installed (groff-base)"; exit 77; }
fail=0
for page in "$src"/docs/man/*.[19]; do
  warnings=$(groff -man -ww -z "$page" 2>&1 || true)
  [ -z "$warnings" ] || { echo "FAIL: $page: groff warns:"; echo "$warnings"; fail=1; }
  if command -v man > /dev/null; then
    text=$(MANWIDTH=80 man -l "$page" 2> "${TMPDIR:-/tmp}/man_pages.$$" | col -b)
    [ ! -s "${TMPDIR:-/tmp}/man_pages.$$" ] || { echo "FAIL: man -l $page:"; cat "${TMPDIR:-/tmp}/man_pages.$$"; fail=1; }
    rm -f "${TMPDIR:-/tmp}/man_pages.$$"
    grep -q '^NAME' <<< "$text" || { echo "FAIL: man -l $page renders no NAME section"; fail=1; }
  fi
  echo "$(basename "$page"): $(groff -man -Tutf8 "$page" 2>/dev/null | wc -l) lines, no warnings"
done

# The names a page must mention, from the source: RTAPI_MP_*(name, ...), "comp.pin-name" strings.
plain() { groff -man -Tascii -P-c -P-b -P-u "$1" 2> /dev/null; }
check_names() {
  local page=$1 source=$2 comp=$3 text missing=()
  text=$(plain "$page")
  while read -r name; do
    grep -qF -- "$name" <<< "$text" || missing+=("$name")
  done < <({
    grep -oE 'RTAPI_MP_[A-Z]+\(([a-z_0-9]+)' "$source" | sed -E 's/.*\(//'
    # pins and params: "comp.x.y" literals; %d becomes N, an axis letter %c x, a bare list entry "name" gets comp.
    grep -oE "\"$comp\\.[a-z0-9%.-]+\"" "$source" | tr -d '"' | grep -v '%s' | sed -e 's/%d/N/g' -e 's/\.tN$/.t1/' -e 's/%c/x/g'
  } | sort -u)
  if ((${#missing[@]})); then echo "FAIL: $(basename "$page") does not mention: ${missing[*]}"; return 1; fi
  echo "$(basename "$page"): names every module parameter, pin and param of $(basename "$source")"
}
check_names "$src/docs/man/firtp.9" "$src/component/hal/firtp.cpp" firtp || fail=1
check_names "$src/docs/man/firtp_tp.9" "$src/component/linuxcnc_tp/tp_module.cpp" firtp_tp || fail=1
# firtp_tp's pins are made from a list of suffixes: each must appear as firtp_tp.SUFFIX
tp_text=$(plain "$src/docs/man/firtp_tp.9")
for suffix in $(grep -oE '\{&pins->[a-z_]+, "[a-z-]+"\}' "$src/component/linuxcnc_tp/tp_module.cpp" | sed -E 's/.*"(.*)".*/\1/'); do
  grep -qF "firtp_tp.$suffix" <<< "$tp_text" || { echo "FAIL: firtp_tp.9 does not mention pin firtp_tp.$suffix"; fail=1; }
done

# Each default a page or the GUIDE states is the one in firtp/defaults.hpp (the modules' and the
# CLI's help texts are made from the same texts there).
defaults_h="$src/component/core/include/firtp/defaults.hpp"
default_text() { sed -nE "s/^#define FIRTP_DEFAULT_$1_TEXT \"(.*)\"$/\1/p" "$defaults_h"; }
period_ns=$(sed -nE "s/.*servo_period_ns = ([0-9']+);.*/\1/p" "$defaults_h" | tr -d "'")
# file, what it must contain (a fixed string), what for
require() {
  grep -qF -- "$2" "$1" || { echo "FAIL: $(basename "$1") does not state $3 as firtp/defaults.hpp does: $2"; fail=1; }
}
tolerance=$(default_text TOLERANCE) reserve=$(default_text RATE_RESERVE)
chord=$(default_text ARC_CHORD_TOLERANCE) override=$(default_text MAX_FEED_OVERRIDE) budget=$(default_text PLAN_BUDGET_US)
for v in "$tolerance" "$reserve" "$chord" "$override" "$period_ns" "$budget"; do
  [ -n "$v" ] || { echo "FAIL: a default missing from $defaults_h"; fail=1; }
done
require "$src/docs/man/firtp.9" "\fBtolerance\fR (machine units, $tolerance)" "tolerance"
require "$src/docs/man/firtp.9" "\fBmax_feed_override\fR ($override)" "max_feed_override"
require "$src/docs/man/firtp.9" "\fBrate_reserve\fR ($reserve)" "rate_reserve"
require "$src/docs/man/firtp.9" "\fBperiod_ns\fR ($period_ns)" "period_ns"
require "$src/docs/man/firtp.9" "\fBplan_budget_us\fR ($budget)" "plan_budget_us"
require "$src/docs/man/firtp_tp.9" "\fBplan_budget_us\fR ($budget)" "plan_budget_us"
require "$src/docs/man/firtp_tp.9" "\fBtolerance\fR ($tolerance)" "tolerance"
require "$src/docs/man/firtp_tp.9" "\fBchord_tol\fR ($chord)" "chord_tol"
require "$src/docs/man/firtp_tp.9" "\fBrate_reserve\fR ($reserve)" "rate_reserve"
require "$src/docs/man/firtp.1" "tolerance $tolerance mm." "the built-in machine's tolerance"
require "$src/docs/GUIDE.md" "\`ARC_CHORD_TOLERANCE\` (mm, $chord)" "ARC_CHORD_TOLERANCE"
require "$src/docs/GUIDE.md" "\`RATE_RESERVE\` (0-1, $reserve:" "RATE_RESERVE"
require "$src/docs/GUIDE.md" "(\`[FIRTP]RATE_RESERVE\`, default $reserve)" "RATE_RESERVE"
require "$src/docs/GUIDE.md" "(\`[DISPLAY]MAX_FEED_OVERRIDE\`, default $override," "MAX_FEED_OVERRIDE"
require "$src/docs/GUIDE.md" "smoothed at those limits, $tolerance mm." "the built-in machine's tolerance"
[ "$fail" = 0 ] && echo "defaults: the man pages and the GUIDE state those of firtp/defaults.hpp"

one=$(plain "$src/docs/man/firtp.1")
for word in plan run serve host simulate record replay "EXIT STATUS" "--version"; do
  grep -qF -- "$word" <<< "$one" || { echo "FAIL: firtp.1 does not mention $word"; fail=1; }
done
grep -qE '^ +3 +' <<< "$one" || { echo "FAIL: firtp.1 lists no exit status 3"; fail=1; }
exit $fail
