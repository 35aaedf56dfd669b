#!/usr/bin/env bash
# RobotRun autograder setup (written by `robotrun autograder`, see docs/grading.md): installs what
# grading needs and is missing, nothing else: a Java 21 or newer, and Mesa's off-screen OpenGL
# (libOSMesa) for the pictures (without it, results have no pictures and say so).
# Ubuntu 22.04 and 24.04 (Gradescope's base images) package openjdk-21; Debian 12 does not (its
# newest is openjdk-17): there a JDK 21+ must already be installed (/usr/lib/jvm, $JAVA_HOME or
# $ROBOTRUN_JAVA), or the bundle made with --runtime.
set -eu
ROOT="${ROBOTRUN_AUTOGRADER_ROOT:-@DEFAULT_ROOT@}"
SOURCE="${ROBOTRUN_AUTOGRADER_SOURCE:-$ROOT/@SOURCE_DIR@}"
. "$SOURCE/robotrun-java.sh"

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo -n"; fi
has_osmesa() { { ldconfig -p 2>/dev/null || /sbin/ldconfig -p 2>/dev/null; } | grep -q 'libOSMesa\.so'; }
updated=""
apt_update() { [ -n "$updated" ] || { $SUDO apt-get update -qq; updated=1; }; }
apt_install() { DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$@"; }

if ! find_java >/dev/null; then
  apt_update
  if apt-cache show openjdk-21-jre-headless >/dev/null 2>&1; then
    echo "setup.sh: installing openjdk-21-jre-headless"
    apt_install openjdk-21-jre-headless
  else
    echo "setup.sh: no Java 21 or newer here, and this system packages none ($(. /etc/os-release 2>/dev/null; echo "${PRETTY_NAME:-unknown system}"); Debian 12 has only openjdk-17)." >&2
    echo "setup.sh: install a JDK 21+ (e.g. Temurin) or build the autograder with --runtime DIR." >&2
    exit 1
  fi
fi
if ! has_osmesa; then
  apt_update
  echo "setup.sh: installing libosmesa6 (pictures)"
  apt_install libosmesa6 || echo "setup.sh: libosmesa6 is not available: results will have no pictures" >&2
fi
java=$(find_java) || { echo "setup.sh: still no Java 21 or newer" >&2; exit 1; }
echo "setup.sh: Java $(java_major "$java") at $java; OSMesa: $(has_osmesa && echo yes || echo no)"
if [ -f "$SOURCE/robotrun.jar" ]; then
  "$java" -jar "$SOURCE/robotrun.jar" --version
fi
