# Finds a Java 21 or newer for ./mvnw and ./robotrun (sourced by both; POSIX sh). Windows: find-jdk.cmd.
#
#   rr_find_java_home javac   prints the home of a JDK 21+ (java and javac), or fails
#   rr_find_java_home java    the same, a runtime is enough
#   rr_no_java_message        the one line to print when there is none
#
# Where it looks, in this order: $JAVA_HOME; the `java` on the PATH (through its symlinks); then
# the newest 21+ among /usr/lib/jvm/*, /usr/java/*, /opt/java/*, /Library/Java/JavaVirtualMachines/*,
# macOS's /usr/libexec/java_home, SDKMAN's candidates ($SDKMAN_DIR or ~/.sdkman), ~/.jdks (IntelliJ)
# and ~/.gradle/jdks. So whatever `java` is the default (17 on a stock Debian 12), an installed JDK
# 21+ is used without setting JAVA_HOME. The version is read from the JDK's `release` file (no JVM
# started), or from `java -version` where there is none.

rr_java_major() {
  # $1 = a Java home; prints its major version (8 for 1.8), nothing when it is not one.
  [ -x "$1/bin/java" ] || return 0
  if [ -f "$1/release" ]; then
    _rr_v=$(sed -n 's/^JAVA_VERSION="\([0-9][0-9.]*\).*/\1/p' "$1/release" | head -n 1)
  else
    _rr_v=$("$1/bin/java" -version 2>&1 | sed -n 's/.* version "\([0-9][0-9.]*\).*/\1/p' | head -n 1)
  fi
  case "$_rr_v" in
  1.*) _rr_v=${_rr_v#1.} ;;
  esac
  printf '%s\n' "${_rr_v%%.*}"
}

rr_usable() {
  # $1 = home, $2 = java|javac: true when it is Java 21+ and has that tool.
  [ -n "$1" ] && [ -x "$1/bin/$2" ] || return 1
  _rr_m=$(rr_java_major "$1")
  [ -n "$_rr_m" ] && [ "$_rr_m" -ge 21 ] 2>/dev/null
}

rr_resolve() {
  # Follows symlinks of a file (readlink -f is not on every macOS).
  _rr_f=$1
  _rr_n=0
  while [ -L "$_rr_f" ] && [ $_rr_n -lt 40 ]; do
    _rr_l=$(ls -l "$_rr_f" | sed 's/.* -> //')
    case "$_rr_l" in
    /*) _rr_f=$_rr_l ;;
    *) _rr_f=$(dirname "$_rr_f")/$_rr_l ;;
    esac
    _rr_n=$((_rr_n + 1))
  done
  printf '%s\n' "$_rr_f"
}

rr_find_java_home() {
  _rr_tool=${1:-javac}
  if rr_usable "${JAVA_HOME-}" "$_rr_tool"; then
    printf '%s\n' "$JAVA_HOME"
    return 0
  fi
  _rr_j=$(command -v java 2>/dev/null || true)
  if [ -n "$_rr_j" ]; then
    _rr_h=$(dirname "$(dirname "$(rr_resolve "$_rr_j")")")
    if rr_usable "$_rr_h" "$_rr_tool"; then
      printf '%s\n' "$_rr_h"
      return 0
    fi
  fi
  _rr_best=""
  _rr_best_m=0
  _rr_glob_off=0
  case $- in *f*) _rr_glob_off=1 ;; esac
  set +f
  _rr_mac=""
  [ -z "${ROBOTRUN_JDK_ROOTS-}" ] && [ -x /usr/libexec/java_home ] && _rr_mac=$(/usr/libexec/java_home -v 21+ 2>/dev/null || true)
  # ROBOTRUN_JDK_ROOTS (folders holding JDK homes, ':'-separated) replaces the system folders: for tests.
  if [ -n "${ROBOTRUN_JDK_ROOTS-}" ]; then
    _rr_sys=$(printf '%s\n' "$ROBOTRUN_JDK_ROOTS" | tr ':' '\n' | sed 's|$|/*|')
  else
    _rr_sys="/usr/lib/jvm/* /usr/java/* /opt/java/* /Library/Java/JavaVirtualMachines/*/Contents/Home"
  fi
  for _rr_h in $_rr_sys "$_rr_mac" "${SDKMAN_DIR:-${HOME:-/nonexistent}/.sdkman}"/candidates/java/* \
    "${HOME:-/nonexistent}"/.jdks/* "${HOME:-/nonexistent}"/.gradle/jdks/*; do
    [ -n "$_rr_h" ] && [ -d "$_rr_h" ] || continue
    rr_usable "$_rr_h" "$_rr_tool" || continue
    _rr_m=$(rr_java_major "$_rr_h")
    if [ "$_rr_m" -gt "$_rr_best_m" ]; then
      _rr_best=$_rr_h
      _rr_best_m=$_rr_m
    fi
  done
  [ $_rr_glob_off -eq 1 ] && set -f
  [ -n "$_rr_best" ] || return 1
  printf '%s\n' "$_rr_best"
}

rr_no_java_message() {
  # One line: what is missing and how to get it on this platform.
  case "$(uname -s 2>/dev/null)" in
  Darwin) _rr_get="brew install --cask temurin@21 (or a JDK from adoptium.net)" ;;
  Linux)
    if command -v apt-get >/dev/null 2>&1; then
      _rr_get="sudo apt-get install openjdk-21-jdk (Debian 13, Ubuntu 24.04; older releases: a JDK from adoptium.net)"
    elif command -v dnf >/dev/null 2>&1; then
      _rr_get="sudo dnf install java-21-openjdk-devel"
    else
      _rr_get="a JDK 21+ from adoptium.net, or sdk install java 21-tem with SDKMAN"
    fi
    ;;
  *) _rr_get="a JDK 21+ from adoptium.net" ;;
  esac
  printf '%s\n' "RobotRun needs a JDK 21 or newer and found none (looked at JAVA_HOME, the PATH, /usr/lib/jvm, /Library/Java/JavaVirtualMachines, SDKMAN, ~/.jdks); install one: $_rr_get"
}
