#!/usr/bin/env bash
# Starts lcm-spy with the firtp_lcm types, so it decodes FIRTP_* messages.
#   lcm-types/lcm-spy.sh [-l URL] [other lcm-spy options]
# URL defaults to firtp's (firtp::messages::default_url()). The types jar is build target
# firtp_lcm_types_jar; FIRTP_LCM_TYPES_JAR overrides where it is looked for.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# installed as PREFIX/bin/firtp-lcm-spy: PREFIX/share/java; in the source tree: build/
jar=$here/../share/java/firtp_lcm_types.jar
[[ -f $jar ]] || jar=$here/../build/lcm-types/firtp_lcm_types.jar
jar=${FIRTP_LCM_TYPES_JAR:-$jar}
default_url='udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608'

missing() {
  echo "lcm-spy.sh: $1" >&2
  echo "  Debian: sudo apt-get install liblcm-java libjchart2d-java default-jdk" >&2
  exit 1
}
command -v lcm-spy >/dev/null || missing "lcm-spy not found (package liblcm-java)"
command -v java >/dev/null || missing "java not found (a JDK: default-jdk, or default-jdk-headless to build the jar)"
[[ -f /usr/share/java/jchart2d.jar ]] || missing "jchart2d.jar not found (package libjchart2d-java)"
if [[ ! -f $jar ]]; then
  echo "lcm-spy.sh: no types jar at $jar" >&2
  echo "  build it: cmake --build build --target firtp_lcm_types_jar" >&2
  echo "  (needs a JDK and liblcm-java: sudo apt-get install default-jdk-headless liblcm-java)" >&2
  exit 1
fi

# Pass every argument through; add the default URL unless one was given.
args=("$@")
has_url=0
for a in "${args[@]}"; do
  case $a in -l | --lcm-url | --lcm-url=*) has_url=1 ;; esac
done
((has_url)) || args=(-l "$default_url" "${args[@]}")

# lcm-spy scans CLASSPATH for LCM types; Java 17 rejects -Xincgc in its launcher unless told to ignore it.
jar=$(realpath "$jar")
export CLASSPATH=$jar${CLASSPATH:+:$CLASSPATH}
export JAVA_TOOL_OPTIONS="-XX:+IgnoreUnrecognizedVMOptions${JAVA_TOOL_OPTIONS:+ $JAVA_TOOL_OPTIONS}"
exec lcm-spy "${args[@]}"
