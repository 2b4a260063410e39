#!/usr/bin/env bash
# Each subcommand on bad input: a non-zero exit status and one line on stderr
# that names the subcommand and the input. Usage: error_paths.sh LRSVO WORK_DIR
set -uo pipefail
lrsvo=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n' > "$work/poses.tum"
failures=0
# expect_failure PATTERN COMMAND...: exit status 1 and the last stderr line matching PATTERN.
expect_failure() {
  local pattern=$1
  shift
  local err status
  err=$("$@" 2>&1 >/dev/null)
  status=$?
  local last
  last=$(printf '%s\n' "$err" | tail -n 1)
  if ((status != 1)) || ! grep -Eq -- "$pattern" <<<"$last"; then
    echo "FAIL: $* -> exit $status, last line: $last (expected exit 1 and /$pattern/)"
    failures=$((failures + 1))
  else
    echo "ok: $* -> $last"
  fi
}
expect_failure '^lrsvo run: error: .*/no/such/sequence' "$lrsvo" run "$work/no/such/sequence" --quiet
expect_failure '^lrsvo run: error: .*nosuch\.yaml' "$lrsvo" run "sim:$work/nosuch.yaml" --quiet
expect_failure '^lrsvo render: error: .*nosuch\.yaml' "$lrsvo" render "$work/nosuch.yaml" --out "$work/render"
expect_failure '^lrsvo eval: file system error: .*/dev/null/out' \
  "$lrsvo" eval "$work/poses.tum" "$work/poses.tum" --no-plot --out /dev/null/out
expect_failure '^lrsvo bal: error: .*no_such\.txt' "$lrsvo" bal "$work/no_such.txt"
expect_failure "^lrsvo study: error: .*no-such-study" "$lrsvo" study no-such-study --out "$work/study"
# A bad option is the command line's error: CLI11's message naming the option and a non-zero status.
for option in "--window 1" "--max-keyframe-rate 2" "--max-keyframe-rate fast"; do
  # shellcheck disable=SC2086 # the option and its value are two words
  err=$("$lrsvo" run sim:demo $option 2>&1 >/dev/null)
  status=$?
  if ((status == 0)) || ! grep -q -- "${option%% *}" <<<"$err"; then
    echo "FAIL: lrsvo run $option -> exit $status: $err"
    failures=$((failures + 1))
  else
    echo "ok: lrsvo run $option -> exit $status"
  fi
done
exit $((failures > 0))
