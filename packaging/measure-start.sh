#!/usr/bin/env bash
# Start-up figures of an unpacked app image (docs/install.md, "Releasing"): median wall and CPU
# (user + system) time of
# 'RobotRun --version' and of launch-to-first-frame ('gui --quit-after-frames 1': the process
# exits right after its first frame is on screen, so this is an upper bound), N runs each, with
# no CDS at all, with the JDK's default CDS only, and with the AppCDS archive the package ships.
# Run the window part under a display: xvfb-run -a -s '-screen 0 1366x768x24' packaging/measure-start.sh DIR
# Usage: packaging/measure-start.sh APP_IMAGE_DIR [RUNS]   (APP_IMAGE_DIR holds bin/RobotRun)
set -euo pipefail
img="$(cd "$1" && pwd)"; runs="${2:-7}"
variants="$(mktemp -d)"
trap 'rm -rf "$variants"' EXIT
mkdir -p "$variants/home"
# The launcher reads its JVM options from lib/app/RobotRun.cfg only (not JDK_JAVA_OPTIONS): each
# variant is a hard-linked copy of the image with its own .cfg.
variant() {  # NAME SED-EXPRESSION
  cp -al "$img" "$variants/$1"
  local cfg="$variants/$1/lib/app/RobotRun.cfg"
  sed "$2" "$img/lib/app/RobotRun.cfg" > "$cfg.new" && rm "$cfg" && mv "$cfg.new" "$cfg"
}
variant nocds 's|^java-options=-XX:SharedArchiveFile=.*|java-options=-Xshare:off|'
variant jdkcds '/^java-options=-XX:SharedArchiveFile=/d'
variant appcds 'p;d'
scenario="$(cd "$(dirname "$0")/.." && pwd)/scenarios/pick-and-place.json"

median() { sort -n | awk '{a[NR]=$1} END {m=(NR%2)?a[(NR+1)/2]:(a[NR/2]+a[NR/2+1])/2; printf "%.3f", m}'; }
one() {  # VARIANT ARGS...: "wall cpu" seconds of one run, with no JDK on the PATH
  local launcher="$variants/$1/bin/RobotRun"; shift
  env -i PATH=/usr/bin:/bin HOME="$variants/home" DISPLAY="${DISPLAY:-}" XAUTHORITY="${XAUTHORITY:-}" \
    /usr/bin/time -f '%e %U %S' -o /dev/stdout "$launcher" "$@" 2>/dev/null | tail -1 | awk '{printf "%.2f %.2f\n", $1, $2 + $3}'
}
series() {
  local label="$1" opts="$2"; shift 2
  one "$opts" "$@" >/dev/null  # warm the disk cache
  local rows=() i
  for ((i = 0; i < runs; i++)); do rows+=("$(one "$opts" "$@")"); done
  printf '%-34s wall median %s s, CPU median %s s   (wall: %s)\n' "$label" \
    "$(printf '%s\n' "${rows[@]}" | cut -d' ' -f1 | median)" "$(printf '%s\n' "${rows[@]}" | cut -d' ' -f2 | median)" \
    "$(printf '%s\n' "${rows[@]}" | cut -d' ' -f1 | tr '\n' ' ')"
}

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)   cpus: $(nproc)"
for what in version frame; do
  if [ "$what" = version ]; then args=(--version); else
    [ -n "${DISPLAY:-}" ] || { echo "no DISPLAY: skipping first-frame times"; continue; }
    args=(gui --scenario "$scenario" --quit-after-frames 1)
  fi
  series "$what, no CDS (-Xshare:off)" nocds "${args[@]}"
  series "$what, JDK default CDS only" jdkcds "${args[@]}"
  series "$what, AppCDS (as packaged)" appcds "${args[@]}"
done
