#!/usr/bin/env bash
# RobotRun autograding step for GitHub Classroom (written by `robotrun autograder github-classroom`,
# see docs/grading.md): grades the hand-in in this repository and gives one step output per check,
# NAME=base64(JSON), which the autograding reporter reads. Whatever goes wrong, every output is
# still given: status "error", zero points and a message saying what to fix.
set -u
ROOT="${ROBOTRUN_AUTOGRADER_ROOT:-${GITHUB_WORKSPACE:-.}}"
SOURCE="$ROOT/.robotrun"
TASK="$SOURCE/@TASK@"
# The longest a grading may take (the task's wall-clock limit plus start-up); ROBOTRUN_AUTOGRADER_GUARD_SECONDS overrides.
GUARD_SECONDS="${ROBOTRUN_AUTOGRADER_GUARD_SECONDS:-@GUARD_SECONDS@}"
# Each check's runner name and points, as the workflow names them.
RUNNERS="@RUNNERS@"
OUT="${GITHUB_OUTPUT:-/dev/stdout}"
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
. "$SOURCE/robotrun-java.sh"
rc=127
if java=$(find_java); then
  GITHUB_OUTPUT="$tmp" timeout -k 10 "$GUARD_SECONDS" "$java" "${ROBOTRUN_JVM_FLAGS[@]}" -jar "$SOURCE/robotrun.jar" \
    autograder run --platform github-classroom --task "$TASK" --root "$ROOT"
  rc=$?
fi
complete=1
for r in $RUNNERS; do
  grep -q "^${r%%:*}=" "$tmp" || complete=""
done
if [ -n "$complete" ]; then
  cat "$tmp" >> "$OUT"
  exit 0
fi
if [ "$rc" -eq 127 ]; then
  msg="Not graded: no Java 21 or newer (the workflow's setup-java step sets it up)."
elif [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
  msg="Not graded: RobotRun was stopped (exit $rc) after at most $GUARD_SECONDS s."
else
  msg="Not graded: RobotRun exited with code $rc (the log above says why)."
fi
echo "grade.sh: $msg"
for r in $RUNNERS; do
  json=$(printf '{"version": 1, "status": "error", "max_score": %s, "tests": [{"name": "%s", "status": "error", "score": 0, "message": "%s"}]}' \
    "${r##*:}" "${r%%:*}" "$msg")
  echo "${r%%:*}=$(printf '%s' "$json" | base64 | tr -d '\n')" >> "$OUT"
done
exit 0
