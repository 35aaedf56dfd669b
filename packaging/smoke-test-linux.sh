#!/usr/bin/env bash
# Smoke test of the Linux packages in DIR (target/packages), with no JDK on the PATH: the .deb
# unpacked into a temporary root (dpkg-deb -x, no root rights needed) and the .tar.gz app image
# each print the version, check and run the example scenario, render a PNG and, when a display or
# xvfb-run is there, open the window for a few frames. With ROBOTRUN_SMOKE_INSTALL=1 (CI, as root
# or with sudo) the .deb is also really installed, 'robotrun' tried from the PATH, and removed.
# Usage: packaging/smoke-test-linux.sh DIR
set -euo pipefail
dir="$(cd "$1" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
# Java takes user.home from the password file, not $HOME: the XDG folders keep the app's
# workspaces, settings and cache in the temporary home.
xdg=(XDG_DATA_HOME="$tmp/home/.local/share" XDG_CONFIG_HOME="$tmp/home/.config" XDG_CACHE_HOME="$tmp/home/.cache")
clean() { env -i PATH=/usr/bin:/bin HOME="$tmp/home" "${xdg[@]}" DISPLAY="${DISPLAY:-}" XAUTHORITY="${XAUTHORITY:-}" "$@"; }
mkdir -p "$tmp/home"
fail() { echo "smoke: FAILED: $*" >&2; exit 1; }

check_app() {  # LAUNCHER APPDIR
  local app="$1" appdir="$2" out="$tmp/out"
  echo "smoke: $app"
  clean "$app" --version | grep -q '^robotrun ' || fail "--version"
  clean "$app" check "$appdir/scenarios/programs" || fail "check the example programs"
  rm -rf "$out"; mkdir -p "$out"
  clean "$app" run --scenario "$appdir/scenarios/pick-and-place.json" --report "$out/report.json" || fail "run the example scenario"
  grep -q '"status"' "$out/report.json" || fail "run report"
  clean "$app" render --scenario "$appdir/scenarios/pick-and-place.json" --out "$out/shot.png" --width 320 --height 240 || fail "render"
  [ "$(head -c 8 "$out/shot.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "render wrote no PNG"
  [ "$(stat -c %s "$out/shot.png")" -gt 2000 ] || fail "render: PNG too small to hold a cell"
  # Bad input: one line, exit 2, no stack trace.
  set +e; clean "$app" run --scenario "$out/missing.json" 2> "$out/err"; code=$?; set -e
  [ "$code" = 2 ] && ! grep -q 'at org\.' "$out/err" || fail "bad input handling (exit $code)"
  if [ "$(uname -m)" != x86_64 ]; then
    # No imgui-java natives for this CPU: the window must say so in one line and exit 1.
    set +e; clean "$app" gui 2> "$out/err"; code=$?; set -e
    [ "$code" = 1 ] && grep -q 'Dear ImGui natives' "$out/err" && ! grep -q 'at org\.' "$out/err" || fail "window message on $(uname -m)"
  else
    # The window, opened the way a file manager opens a .rrcell file: 'RobotRun FILE'.
    cp "$appdir/scenarios/pick-and-place.json" "$appdir/scenarios/smoke.rrcell"
    if [ -n "${DISPLAY:-}" ]; then clean "$app" "$appdir/scenarios/smoke.rrcell" --quit-after-frames 3 || fail "window"
    elif command -v xvfb-run >/dev/null; then
      xvfb-run -a -s '-screen 0 1366x768x24' bash -c 'env -i PATH=/usr/bin:/bin HOME="$0" XDG_DATA_HOME="$0/.local/share" XDG_CONFIG_HOME="$0/.config" XDG_CACHE_HOME="$0/.cache" DISPLAY="$DISPLAY" XAUTHORITY="$XAUTHORITY" "$@"' \
        "$tmp/home" "$app" "$appdir/scenarios/smoke.rrcell" --quit-after-frames 3 || fail "window"
    else
      echo "smoke: no display and no xvfb-run: window not tried"
      touch "$tmp/no-window"
    fi
    rm -f "$appdir/scenarios/smoke.rrcell"
    [ -e "$tmp/no-window" ] || ls "$tmp"/home/.local/share/robotrun/workspaces/ 2>/dev/null | grep -q '^smoke' \
      || fail "opening a .rrcell made no workspace"
  fi
  echo "smoke: ok: version, check, run, render, bad input, window"
}

deb=$(ls "$dir"/*.deb | head -1)
echo "smoke: $(basename "$deb") $(stat -c %s "$deb") bytes"
dpkg-deb -x "$deb" "$tmp/root"
dpkg-deb -e "$deb" "$tmp/control"
grep -q 'ln -sf /opt/robotrun/bin/RobotRun /usr/bin/robotrun' "$tmp/control/postinst" || fail "postinst does not put robotrun on the PATH"
grep -q '^Exec=/opt/robotrun/bin/RobotRun %f$' "$tmp"/root/opt/robotrun/lib/*.desktop || fail "no menu entry passing the opened file"
grep -rqi 'text/x-robotrun-tp' "$tmp"/root/opt/robotrun/lib/*.xml 2>/dev/null || fail "no .LS file association (shared-mime-info)"
grep -rq 'pattern="\*\.rrcell"' "$tmp"/root/opt/robotrun/lib/*.xml 2>/dev/null || fail "no .rrcell file association (shared-mime-info)"
grep -q '^MimeType=.*text/x-robotrun-tp.*' "$tmp"/root/opt/robotrun/lib/*.desktop || fail "menu entry without the .LS type"
grep -q '^MimeType=.*application/x-robotrun-cell' "$tmp"/root/opt/robotrun/lib/*.desktop || fail "menu entry without the .rrcell type"
check_app "$tmp/root/opt/robotrun/bin/RobotRun" "$tmp/root/opt/robotrun/lib/app"

tgz=$(ls "$dir"/*.tar.gz | head -1)
mkdir -p "$tmp/portable"
tar -xzf "$tgz" -C "$tmp/portable"
check_app "$tmp/portable/RobotRun/bin/RobotRun" "$tmp/portable/RobotRun/lib/app"

if [ "${ROBOTRUN_SMOKE_INSTALL:-}" = 1 ]; then
  sudo=""; [ "$(id -u)" = 0 ] || sudo=sudo
  $sudo apt-get install -y -qq "$deb"
  clean robotrun --version || fail "robotrun on the PATH after installing"
  $sudo apt-get remove -y -qq robotrun
  [ ! -e /usr/bin/robotrun ] || fail "/usr/bin/robotrun left after removing"
fi
echo "smoke: all Linux package checks passed"
