#!/bin/sh
# Runs a command and checks its exit code and that its output (stdout + stderr)
# matches an extended regular expression (on one line, or across lines).
#   cli-expect.sh EXPECTED_EXIT REGEX COMMAND [ARGS...]
# The environment variable CLI_UNSET_DISPLAY=1 runs the command without DISPLAY;
# CLI_ULIMIT_V=KiB runs it under `ulimit -v KiB`; CLI_NEEDS_FILE=PATH skips (exit 125)
# when PATH does not exist.
expected=$1
pattern=$2
shift 2
if [ -n "${CLI_NEEDS_FILE:-}" ] && [ ! -e "$CLI_NEEDS_FILE" ]; then
  echo "skipped: $CLI_NEEDS_FILE is absent"
  exit 125
fi
if [ -n "${CLI_ULIMIT_V:-}" ]; then
  ulimit -v "$CLI_ULIMIT_V" || exit 1
fi
if [ "${CLI_UNSET_DISPLAY:-0}" = 1 ]; then
  output=$(env -u DISPLAY "$@" 2>&1)
else
  output=$("$@" 2>&1)
fi
code=$?
printf '%s\n' "$output"
if [ "$code" != "$expected" ]; then
  echo "cli-expect: exit code $code, expected $expected"
  exit 1
fi
# A line must match, or the whole output taken as one line (newlines as spaces), for
# patterns that span lines.
if ! printf '%s\n' "$output" | grep -Eq -- "$pattern" &&
  ! printf '%s\n' "$output" | tr '\n' ' ' | grep -Eq -- "$pattern"; then
  echo "cli-expect: output does not match: $pattern"
  exit 1
fi
exit 0
