#!/bin/sh
# Runs a command and checks its exit code and that its output (stdout + stderr)
# matches an extended regular expression.
#   cli-expect.sh EXPECTED_EXIT REGEX COMMAND [ARGS...]
# The environment variable CLI_UNSET_DISPLAY=1 runs the command without DISPLAY.
expected=$1
pattern=$2
shift 2
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
if ! printf '%s\n' "$output" | grep -Eq -- "$pattern"; then
  echo "cli-expect: output does not match: $pattern"
  exit 1
fi
exit 0
