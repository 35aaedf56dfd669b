#!/usr/bin/env bash
# RobotRun external grader for PrairieLearn (written by `robotrun autograder prairielearn`, see
# docs/grading.md): grades the hand-in in $ROOT/student against the question's task in
# $ROOT/tests and writes $ROOT/results/results.json. Whatever goes wrong, valid results are
# written: not gradable (the student loses no attempt) and a message saying what to fix.
set -u
ROOT="${ROBOTRUN_AUTOGRADER_ROOT:-/grade}"
SOURCE="$ROOT/serverFilesCourse/robotrun"
RESULTS="$ROOT/results/results.json"
TASK="$ROOT/tests/@TASK@"
# The longest a grading may take (the task's wall-clock limit plus start-up); ROBOTRUN_AUTOGRADER_GUARD_SECONDS overrides.
GUARD_SECONDS="${ROBOTRUN_AUTOGRADER_GUARD_SECONDS:-@GUARD_SECONDS@}"
mkdir -p "$ROOT/results"
rm -f "$RESULTS"
# $1: the message (text from this script only: no quotes or backslashes).
fail() {
  printf '{"gradable": false, "score": 0.0, "message": "%s", "format_errors": ["%s"]}\n' "$1" "$1" > "$RESULTS"
  echo "run.sh: $1"
}
. "$SOURCE/robotrun-java.sh"
if ! java=$(find_java); then
  fail "Not graded: no Java 21 or newer in the grading image. Instructor: use an image with Java 21 (see docs/grading.md)."
  exit 0
fi
timeout -k 5 "$GUARD_SECONDS" "$java" "${ROBOTRUN_JVM_FLAGS[@]}" -jar "$SOURCE/robotrun.jar" \
  autograder run --platform prairielearn --task "$TASK" --root "$ROOT"
rc=$?
if [ ! -s "$RESULTS" ]; then
  if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    fail "Not graded: RobotRun was stopped (exit $rc) after at most $GUARD_SECONDS s (time or memory limit). Instructor: raise the question timeout in info.json."
  else
    fail "Not graded: RobotRun exited with code $rc and wrote no results. Instructor: the grading job output says why."
  fi
fi
exit 0
