#!/usr/bin/env bash
# Sourced: builds the Debian package from BUILD ($build) with cpack into $build/package and sets
# $deb to its path. cpack installs the build into a staging tree under $build/_CPack_Packages.
rm -f "$build"/package/firtp_*.deb
if ! (cd "$build" && cpack --config CPackConfig.cmake -G DEB) > "$work/cpack.log" 2>&1; then
  echo "FAIL: cpack"; cat "$work/cpack.log"; exit 1
fi
debs=("$build"/package/firtp_*.deb)
[ "${#debs[@]}" -eq 1 ] && [ -f "${debs[0]}" ] || { echo "FAIL: cpack made no single firtp_*.deb"; cat "$work/cpack.log"; exit 1; }
deb=${debs[0]}
echo "built $deb ($(stat -c %s "$deb") bytes)"
