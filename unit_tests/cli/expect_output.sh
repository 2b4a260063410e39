#!/usr/bin/env bash
# Runs a command and passes only when it exits with status 0 and its output
# (stdout and stderr) matches an extended regular expression across lines.
# Usage: expect_output.sh REGEX COMMAND [ARG ...]
set -uo pipefail
pattern=$1
shift
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if ((status != 0)); then
  echo "FAIL: exit status $status: $*" >&2
  exit 1
fi
if ! printf '%s' "$output" | tr '\n' ' ' | grep -Eq -- "$pattern"; then
  echo "FAIL: the output does not match: $pattern" >&2
  exit 1
fi
