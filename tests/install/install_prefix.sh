#!/usr/bin/env bash
# cmake --install BUILD --prefix (a fresh temporary directory); then, from a directory outside the
# source and build trees, the installed programs run on what was installed: --version, firtp plan
# and firtp run on the installed diamond (run loads the installed lib/firtp/firtp.so), firtp-hal
# loading the installed firtp.so by name, and the man pages.
set -euo pipefail
build=$(cd "$1" && pwd) version=$2 linuxcnc=$3
work=$(mktemp -d /tmp/firtp-install.XXXXXX)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fail() { echo "FAIL: $*"; exit 1; }

cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
echo "installed $(grep -c -- '-- Installing' "$work/install.log") files into $prefix"

expect=(bin/firtp bin/firtp-hal bin/firtp-lcm-dump bin/firtp-tp-check bin/firtp-lcm-spy lib/firtp/firtp.so
  lib/firtp/libfirtp_hal_shim.so
  share/man/man1/firtp.1.gz share/man/man9/firtp.9.gz share/man/man9/firtp_tp.9.gz
  share/firtp/lcm-types/block_t.lcm share/doc/firtp/README.md share/doc/firtp/LICENSE
  share/doc/firtp/examples/diamond.ngc share/doc/firtp/examples/diamond.ini share/doc/firtp/examples/hal/pins.hal
  share/doc/firtp/examples/linuxcnc/firtp_tp.ini share/doc/firtp/examples/linuxcnc/bin/firtp-headless)
if [ "$linuxcnc" = 1 ]; then expect+=(lib/linuxcnc/modules/firtp.so lib/linuxcnc/modules/firtp_tp.so); fi
for f in "${expect[@]}"; do [ -e "$prefix/$f" ] || fail "$f not installed"; done
for f in bin/firtp bin/firtp-hal bin/firtp-lcm-dump bin/firtp-tp-check bin/firtp-lcm-spy share/doc/firtp/examples/linuxcnc/bin/firtp-headless; do
  [ -x "$prefix/$f" ] || fail "$f is not executable"
done
echo "all ${#expect[@]} expected files are there"

# Nothing installed points back into the build tree (RUNPATH, or a path compiled in): the only
# RUNPATHs are relative to the file ($ORIGIN), to hal-shim's runtime in lib/firtp.
for f in "$prefix"/bin/* "$prefix"/lib/firtp/*.so "$prefix"/lib/linuxcnc/modules/*.so; do
  [ -e "$f" ] || continue
  runpath=$(readelf -d "$f" 2> /dev/null | sed -n 's/.*R\(UN\)\?PATH.*\[\(.*\)\]/\2/p') || true
  case "$runpath" in "" | '$ORIGIN' | '$ORIGIN/../lib/firtp') ;; *) fail "$f has the RUNPATH $runpath" ;; esac
  if grep -qF "$build" "$f"; then fail "$f contains the build directory $build"; fi
done
echo "no build path in the installed programs and modules; RUNPATHs only \$ORIGIN-relative"

cd "$work"
got=$("$prefix/bin/firtp" --version)
[ "$got" = "firtp $version" ] || fail "firtp --version printed '$got', expected 'firtp $version'"
for tool in firtp-hal firtp-lcm-dump firtp-tp-check; do
  [ "$("$prefix/bin/$tool" --version)" = "$tool $version" ] || fail "$tool --version"
done
echo "--version: firtp $version on every tool"

ex=$prefix/share/doc/firtp/examples
"$prefix/bin/firtp" plan "$ex/diamond.ngc" --ini "$ex/diamond.ini" --json plan.json > plan.txt || { cat plan.txt; fail "firtp plan"; }
grep -q 'all within tolerance' plan.txt || { cat plan.txt; fail "firtp plan: corners not all within tolerance"; }
cycle=$(grep -oE '"cycle_time_s": *[0-9.]+' plan.json | grep -oE '[0-9.]+$')
awk -v c="$cycle" 'BEGIN { exit !(c > 1.224 && c < 1.226) }' || fail "installed firtp plan: cycle time $cycle s, expected 1.225 s"
echo "installed firtp plan: the diamond in $cycle s, every corner within tolerance"

env -u FIRTP_MODULE "$prefix/bin/firtp" run "$ex/diamond.ngc" --ini "$ex/diamond.ini" --csv run.csv > run.txt 2>&1 || { cat run.txt; fail "firtp run"; }
grep -qE 'largest difference from the plan 0 mm' run.txt || { cat run.txt; fail "firtp run: the chain differs from the plan"; }
echo "installed firtp run (chain with the installed firtp.so): $(grep -oE '[0-9]+ axis states back' run.txt), equal to the plan"

cat > pins.hal << 'HAL'
loadrt threads name1=servo-thread period1=1000000
loadrt firtp t1=0.1 t2=0.05 tolerance=0.02
show param firtp.t1
HAL
env -u FIRTP_HAL_MODULE_PATH "$prefix/bin/firtp-hal" --no-realtime -f pins.hal > hal.txt 2>&1 || { cat hal.txt; fail "installed firtp-hal: loadrt firtp"; }
grep -qE 'RO +0\.1 +firtp\.t1$' hal.txt || { cat hal.txt; fail "installed firtp-hal: no param firtp.t1"; }
echo "installed firtp-hal loads the installed firtp.so by name"

# firtp-lcm-spy hands lcm-spy the installed types jar (a stand-in lcm-spy prints its CLASSPATH).
if [ -e "$prefix/share/java/firtp_lcm_types.jar" ] && [ -e /usr/share/java/jchart2d.jar ]; then
  mkdir fake && printf '#!/bin/sh\necho "CLASSPATH=$CLASSPATH"\n' > fake/lcm-spy && cp fake/lcm-spy fake/java
  chmod +x fake/lcm-spy fake/java
  spy=$(PATH=$work/fake:$PATH "$prefix/bin/firtp-lcm-spy") || fail "firtp-lcm-spy"
  [[ "$spy" == "CLASSPATH=$prefix/share/java/firtp_lcm_types.jar"* ]] || fail "firtp-lcm-spy: $spy"
  echo "installed firtp-lcm-spy uses the installed types jar"
fi

if command -v man > /dev/null; then
  for page in man1/firtp.1.gz man9/firtp.9.gz man9/firtp_tp.9.gz; do
    text=$(MANWIDTH=80 man -l "$prefix/share/man/$page" 2>&1)  # whole, not into grep -q: SIGPIPE
    grep -q '^NAME' <<< "$text" || fail "man -l $page"
  done
  MANPATH=$prefix/share/man man -w 9 firtp_tp > /dev/null || fail "man 9 firtp_tp with MANPATH=$prefix/share/man"
  echo "man pages render from the prefix (man 9 firtp_tp found through MANPATH)"
fi
echo "PASS"
