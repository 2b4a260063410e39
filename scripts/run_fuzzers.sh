#!/usr/bin/env bash
# Runs every libFuzzer target of a `make fuzz` build for a set time each, from
# the committed seeds (unit_tests/fuzz/corpus/<parser>/) plus what earlier runs
# in the same build folder found, and prints per target the executions, the
# corpus size and the failing inputs found. A failing input is kept under
# FUZZ_DIR/crashes/<parser>/; once its cause is fixed, copy it into the
# parser's corpus folder, where the unit tests replay it. Exits 1 when any
# target found one.
# Usage: scripts/run_fuzzers.sh FUZZ_DIR SECONDS
set -uo pipefail
fuzz_dir=$1
seconds=$2
seeds=$(cd "$(dirname "$0")/../unit_tests/fuzz/corpus" && pwd)
failed=0
printf '%-18s %12s %10s %8s %9s\n' target executions exec/s corpus failures
for binary in "$fuzz_dir"/bin/fuzz_*; do
  parser=${binary##*/fuzz_}
  corpus="$fuzz_dir/corpus/$parser"
  crashes="$fuzz_dir/crashes/$parser"
  mkdir -p "$corpus" "$crashes"
  log="$fuzz_dir/logs/$parser.log"
  mkdir -p "$(dirname "$log")"
  # An input that makes a parser allocate gigabytes (-rss_limit_mb) or take 10 s (-timeout) is a finding too.
  "$binary" "$corpus" "$seeds/$parser" -max_total_time="$seconds" -print_final_stats=1 -rss_limit_mb=2048 \
    -timeout=10 -artifact_prefix="$crashes/" -close_fd_mask=3 >"$log" 2>&1
  status=$?
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  found=$(find "$crashes" -type f | wc -l)
  printf '%-18s %12s %10s %8s %9s\n' "$parser" "${executions:-?}" "${rate:-?}" "$(find "$corpus" -type f | wc -l)" "$found"
  if ((status != 0 || found > 0)); then
    failed=1
    echo "  $parser: exit $status; see $log and $crashes/"
  fi
done
exit $failed
