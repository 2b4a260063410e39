#!/usr/bin/env bash
# `lrsvo run` stopped part-way. SIGINT and SIGTERM: the run stops after the
# current frame, exits with 128 + the signal, and leaves whole outputs for the
# frames done (frames.csv, trajectory.tum, metrics.json saying so). SIGKILL:
# whatever was written is whole lines.
# Usage: run_interrupted.sh LRSVO WORK_DIR
set -euo pipefail
lrsvo=$1
work=$2
rm -rf "$work"
mkdir -p "$work"

frames_csv_fields=28
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Starts a run on the demo flight and waits until frames.csv has at least $2 data lines.
start_run() {
  local out=$1 lines=$2
  "$lrsvo" run sim:demo --frames 600 --no-plot --quiet --out "$out" >"$out.stdout" 2>"$out.stderr" &
  pid=$!
  for _ in $(seq 1 1200); do
    if [[ -f "$out/frames.csv" ]] && (($(wc -l <"$out/frames.csv") > lines)); then return 0; fi
    kill -0 "$pid" 2>/dev/null || fail "the run ended before it was signalled: $(cat "$out.stderr")"
    sleep 0.1
  done
  fail "no progress in frames.csv after 120 s"
}

# Every line of frames.csv has the header's field count, every trajectory line 8 numbers.
check_whole_lines() {
  local out=$1
  awk -F, -v n=$frames_csv_fields 'NF != n { print "frames.csv line " NR " has " NF " fields"; bad = 1 }
    END { exit bad }' "$out/frames.csv" || fail "broken frames.csv line in $out"
  awk '!/^#/ && !(NF == 8 || (NF == 10 && $9 == "#" && $10 == "predicted")) { print "trajectory.tum line " NR " has " NF " fields"; bad = 1 } END { exit bad }' \
    "$out/trajectory.tum" || fail "broken trajectory.tum line in $out"
  [[ -z "$(tail -c 1 "$out/frames.csv")" ]] || fail "frames.csv of $out ends mid-line"
}

for signal in INT TERM; do
  out="$work/$signal"
  start_run "$out" 40
  kill "-$signal" "$pid"
  status=0
  wait "$pid" || status=$?
  expected=$((128 + $(kill -l "$signal")))
  ((status == expected)) || fail "SIG$signal: exit status $status, expected $expected; $(tail -3 "$out.stderr")"
  check_whole_lines "$out"
  [[ -f "$out/metrics.json" ]] || fail "SIG$signal: no metrics.json"
  data_lines=$(($(wc -l <"$out/frames.csv") - 1))
  python3 - "$out/metrics.json" "$data_lines" <<'PY' || fail "SIG$signal: metrics.json disagrees with frames.csv"
import json, sys
metrics = json.load(open(sys.argv[1]))
lines = int(sys.argv[2])
assert metrics["stopped_early"] is True, metrics["stopped_early"]
assert metrics["frames"] == lines, (metrics["frames"], lines)
assert 40 <= metrics["frames"] < 600, metrics["frames"]
PY
  grep -q "stopped early by a signal" "$out.stdout" || fail "SIG$signal: the summary does not say it stopped early"
  echo "SIG$signal: exit $status after $data_lines frames, outputs whole"
done

out="$work/KILL"
start_run "$out" 40
kill -KILL "$pid"
wait "$pid" || true
check_whole_lines "$out"
echo "SIGKILL: $(($(wc -l <"$out/frames.csv") - 1)) whole frames.csv lines"
