#!/usr/bin/env bash
# The Debian package cpack builds: the files it holds (dpkg-deb -c), its control fields (dpkg-deb -I)
# and that Depends names the package of every library the packaged programs and modules need
# (readelf NEEDED, resolved with ldconfig, owned per dpkg -S) or LinuxCNC (rtapi_app provides the
# HAL symbols the modules leave undefined).
set -euo pipefail
build=$(cd "$1" && pwd) version=$2 linuxcnc=$3
command -v dpkg-deb > /dev/null || { echo "SKIPPED: no dpkg-deb (not Debian)"; exit 77; }
work=$(mktemp -d /tmp/firtp-deb.XXXXXX)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
source "$here/make_deb.sh"

dpkg-deb -I "$deb" > "$work/info.txt"
field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = firtp ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version: $(field Version), expected $version"
[ "$(field Architecture)" = "$(dpkg --print-architecture)" ] || fail "Architecture: $(field Architecture)"
depends=$(field Depends)
echo "Package firtp $(field Version) $(field Architecture); Depends: $depends"

dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|' > "$work/files.txt"
expect=(/usr/bin/firtp /usr/bin/firtp-hal /usr/bin/firtp-lcm-dump /usr/bin/firtp-tp-check /usr/bin/firtp-lcm-spy
  /usr/lib/firtp/firtp.so /usr/share/man/man1/firtp.1.gz /usr/share/man/man9/firtp.9.gz /usr/share/man/man9/firtp_tp.9.gz
  /usr/share/firtp/lcm-types/block_t.lcm /usr/share/doc/firtp/examples/diamond.ngc /usr/share/doc/firtp/LICENSE
  /usr/share/doc/firtp/copyright)
if [ "$linuxcnc" = 1 ]; then
  moddir=$(sed -n 's/^RTLIBDIR := \(\/.*\)$/\1/p' /usr/share/linuxcnc/Makefile.modinc 2> /dev/null | tail -1)
  moddir=${moddir:-/usr/lib/linuxcnc/modules}
  expect+=("$moddir/firtp.so" "$moddir/firtp_tp.so" /usr/bin/firtp-lcm-bridge)
  grep -q 'linuxcnc-uspace' <<< "$depends" || fail "Depends does not name linuxcnc-uspace"
fi
for f in "${expect[@]}"; do grep -qx -- "$f" "$work/files.txt" || fail "$f is not in the package"; done
if [ -n "$(grep -vE '^/usr/|^/$' "$work/files.txt" || true)" ]; then
  fail "files outside /usr: $(grep -vE '^/usr/|^/$' "$work/files.txt" | tr '\n' ' ')"
fi
echo "$(grep -vc '/$' "$work/files.txt") files, all under /usr, the ${#expect[@]} expected among them"
owners=$(dpkg-deb -c "$deb" | awk '{print $2}' | sort -u)
[ "$owners" = root/root ] || fail "files not owned by root/root: $owners"

# Every NEEDED library of every packaged ELF file comes from a package that Depends names.
mkdir "$work/root"
dpkg-deb -x "$deb" "$work/root"
declare -A needed_from=()
while IFS= read -r f; do
  readelf -h "$f" > /dev/null 2>&1 || continue
  runpath=$(readelf -d "$f" | sed -n 's/.*R\(UN\)\?PATH.*\[\(.*\)\]/\2/p')
  for lib in $(readelf -d "$f" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
    # in the package itself, where the file's $ORIGIN RUNPATH points
    if [ -n "$runpath" ] && [ -e "${runpath//\$ORIGIN/$(dirname "$f")}/$lib" ]; then continue; fi
    # (no early exit in awk: ldconfig would die of SIGPIPE, and pipefail fail the test)
    path=$(ldconfig -p | awk -v l="$lib" '$1 == l && /x86-64|x86_64|64bit/ && !p {p = $NF} END {print p}')
    [ -n "$path" ] || path=$(ldconfig -p | awk -v l="$lib" '$1 == l && !p {p = $NF} END {print p}')
    [ -n "$path" ] || fail "$f needs $lib, which ldconfig does not know"
    owner=$(dpkg -S "$(readlink -f "$path")" 2> /dev/null | sed -n '1s/:.*//p') || true
    [ -n "$owner" ] || owner=$(dpkg -S "$path" 2> /dev/null | sed -n '1s/:.*//p') || true
    [ -n "$owner" ] || fail "$f needs $lib ($path), which no package owns"
    needed_from[$owner]+="${f#"$work/root"} "
  done
done < <(find "$work/root" -type f)
depends_names=$(sed -e 's/ *([^)]*)//g' -e 's/ *, */\n/g' <<< "$depends")  # names, one a line
for owner in "${!needed_from[@]}"; do
  grep -qxF "$owner" <<< "$depends_names" || fail "Depends lacks $owner (needed by ${needed_from[$owner]})"
  echo "  $owner: needed by $(wc -w <<< "${needed_from[$owner]}") files, in Depends"
done
echo "PASS"
