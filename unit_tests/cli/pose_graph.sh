#!/usr/bin/env bash
# `lrsvo graph` on g2o's example pose graphs (SE2 and SE3): exit status 0, a
# final cost below the initial one, an output file that loads again; the same
# seed generating the same file; bad input failing with exit status 1 and a
# message naming the file and line. Exits 77 (skipped) without the data.
# Usage: pose_graph.sh LRSVO POSE_GRAPHS_DIR WORK_DIR
set -uo pipefail
lrsvo=$1
data=$2
work=$3
if [[ ! -f "$data/pose2example.txt" || ! -f "$data/pose3example.txt" ]]; then
  echo "SKIP: no $data/pose2example.txt or pose3example.txt (../shared/data is not beside the repository)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# solve NAME ARGS...: runs lrsvo graph, expects exit 0 and final cost < initial cost.
solve() {
  local name=$1
  shift
  local output status
  output=$("$lrsvo" graph "$@" 2>&1)
  status=$?
  printf '%s\n' "$output" | tail -n 3
  if ((status != 0)); then
    fail "$name: exit $status"
    return
  fi
  local line
  line=$(grep -E '^graph: initial cost' <<<"$output")
  if ! python3 - "$line" <<'PY'; then
import re, sys
m = re.match(r"graph: initial cost (\S+), final cost (\S+), (\d+) iterations", sys.argv[1])
assert m, f"no summary line in: {sys.argv[1]!r}"
initial, final = float(m.group(1)), float(m.group(2))
assert final < initial, f"final cost {final} is not below the initial {initial}"
PY
    fail "$name: $line"
  fi
}

for example in pose2example pose3example; do
  solve "$example" "$data/$example.txt" --out "$work/$example.g2o"
  [[ -s "$work/$example.g2o" ]] || fail "$example: no output file"
  # The optimised file loads again, gauge and all (its first vertex fixed by a FIX line now).
  grep -q '^FIX ' "$work/$example.g2o" || fail "$example: the output has no FIX line"
  "$lrsvo" graph "$work/$example.g2o" --no-solve --out "$work/$example.again.g2o" >/dev/null ||
    fail "$example: the output does not load"
  cmp -s "$work/$example.g2o" "$work/$example.again.g2o" || fail "$example: load and save changed the output"
done
solve "pose3example gn_dense" "$data/pose3example.txt" --solver gn_dense

# The same seed, the same graph; another seed, another graph.
for run in 5a:5 5b:5 6:6; do
  "$lrsvo" graph --generate grid --dimension 2 --poses 300 --seed "${run#*:}" --write "$work/grid_${run%:*}.g2o" \
    --no-solve >/dev/null || fail "generate grid seed ${run#*:}"
done
cmp -s "$work/grid_5a.g2o" "$work/grid_5b.g2o" || fail "the same seed generated different graphs"
cmp -s "$work/grid_5a.g2o" "$work/grid_6.g2o" && fail "seeds 5 and 6 generated the same graph"
solve "generated sphere" --generate sphere --poses 400 --seed 2

# expect_failure PATTERN ARGS...: exit status 1 and the last stderr line matching PATTERN.
expect_failure() {
  local pattern=$1
  shift
  local err status
  err=$("$lrsvo" graph "$@" 2>&1 >/dev/null)
  status=$?
  local last
  last=$(printf '%s\n' "$err" | tail -n 1)
  if ((status != 1)) || ! grep -Eq -- "$pattern" <<<"$last"; then
    fail "lrsvo graph $* -> exit $status, last line: $last (expected exit 1 and /$pattern/)"
  else
    echo "ok: lrsvo graph $* -> $last"
  fi
}
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 7 1 0 0 1 0 0 1 0 1\n' >"$work/missing_vertex.g2o"
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_XY 1 1 0\n' >"$work/unknown_tag.g2o"
expect_failure '^lrsvo graph: error: .*no_such\.g2o' "$work/no_such.g2o"
expect_failure '^lrsvo graph: error: .*missing_vertex\.g2o:3: .*vertex 7' "$work/missing_vertex.g2o"
expect_failure '^lrsvo graph: error: .*unknown_tag\.g2o:2: .*VERTEX_XY' "$work/unknown_tag.g2o"
expect_failure '^lrsvo graph: error: .*no_such_solver' "$data/pose2example.txt" --solver lm_no_such_solver
expect_failure '^lrsvo graph: error: .*FILE' --solver lm_cholmod
# A bad option is the command line's error: a non-zero status.
"$lrsvo" graph "$data/pose2example.txt" --max-iterations -1 >/dev/null 2>&1 && fail "--max-iterations -1 accepted"
exit $((failures > 0))
