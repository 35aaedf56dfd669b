# RobotRun autograder: finds a Java 21 or newer (sourced by setup.sh and the grading scripts).
# Looks at, in order: $ROBOTRUN_JAVA, the runtime bundled with the autograder ($SOURCE/runtime),
# $JAVA_HOME, the JDKs in /usr/lib/jvm, java on the PATH.
java_major() { "$1" -version 2>&1 | sed -n 's/.*version "\([0-9]*\).*/\1/p' | head -1; }
find_java() {
  local c v
  for c in "${ROBOTRUN_JAVA:-}" "${SOURCE:-.}/runtime/bin/java" "${JAVA_HOME:+$JAVA_HOME/bin/java}" \
           /usr/lib/jvm/*/bin/java "$(command -v java 2>/dev/null || true)"; do
    [ -n "$c" ] && [ -x "$c" ] || continue
    v=$(java_major "$c")
    if [ -n "$v" ] && [ "$v" -ge 21 ]; then echo "$c"; return 0; fi
  done
  return 1
}
# The JVM flags for grading one hand-in in a small container: a bounded heap, the serial collector
# (no GC threads to share half a CPU with), no window.
ROBOTRUN_JVM_FLAGS=(-Xmx@XMX_MB@m -XX:+UseSerialGC -Djava.awt.headless=true --enable-native-access=ALL-UNNAMED)
