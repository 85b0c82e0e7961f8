#!/usr/bin/env bash
# Reads every G-code file of a corpus folder (default ../shared/corpus beside the repository) with
# LinuxCNC 2.9's `rs274 -g` and plans it with `firtp plan` on the built-in machine; prints one row
# per program and the totals (docs/GCODE.md has the table). Exit 1 when a program rs274 accepts is
# refused by firtp, or a refusal lacks "FILE:LINE: " with LinuxCNC's reason.
# usage: corpus_check.sh FIRTP [CORPUS_DIR] [RS274]
set -u
firtp=$1
corpus=${2:-$(dirname "$0")/../../../shared/corpus}
rs274=${3:-rs274}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# rs274 gets firtp's built-in tool table (T1..T999, zero offsets) instead of its sample one.
for t in $(seq 1 999); do echo "T$t P$t Z0 D0"; done >"$work/tools.tbl"
accepted=0 planned=0 over=0 refused_both=0 bad=0 total=0
printf '%-45s %-8s %-10s %s\n' program rs274 firtp reason
for f in "$corpus"/*; do
  case "$f" in *.ngc|*.nc|*.gcode|*.tap|*.cnc) ;; *) continue ;; esac
  total=$((total + 1))
  name=$(basename "$f")
  # HOME: rs274's libtooldata maps $HOME/.tool.mmap and truncates it (a running LinuxCNC's table)
  (cd "$work" && HOME="$work" timeout 120 "$rs274" -g -t "$work/tools.tbl" "$f" >"$work/canon" 2>"$work/rs274.err" </dev/null)
  rs=$?
  (ulimit -v 8000000; timeout 300 "$firtp" plan "$f" >"$work/plan.out" 2>"$work/plan.err")  # 8 GB at most (plan keeps every sample)
  fp=$?
  reason=$(grep -m1 "^firtp: " "$work/plan.err" | cut -c1-110)
  if [ $rs -eq 0 ]; then r=accepts; accepted=$((accepted + 1)); else r=refuses; fi
  case $fp in
    0) p=plans; planned=$((planned + 1)) ;;
    3) p=over; over=$((over + 1)); reason=$(grep -m1 -v '^$' "$work/plan.err" | cut -c1-110) ;;
    *) p=refuses ;;
  esac
  if [ $rs -ne 0 ] && [ $fp -ne 0 ] && [ $fp -ne 3 ]; then
    refused_both=$((refused_both + 1))
    # LinuxCNC's reason: the first line of rs274's stderr that is not its banner
    lcnc=$(grep -v '^executing$' "$work/rs274.err" | head -1)
    if ! grep -q "^firtp: $f:[0-9]*: " "$work/plan.err" || ! grep -qF "$lcnc" "$work/plan.err"; then
      bad=$((bad + 1)); p="$p(!)"; reason="$reason | rs274: $lcnc"
    fi
  elif [ $rs -eq 0 ] && [ $fp -ne 0 ]; then
    bad=$((bad + 1)); p="$p(!)"
  fi
  printf '%-45s %-8s %-10s %s\n' "$name" "$r" "$p" "$reason"
done
echo
echo "programs $total; rs274 -g accepts $accepted; firtp plan plans $planned within tolerance and limits, $over over;" \
  "both refuse $refused_both; mismatches $bad"
[ $bad -eq 0 ]
