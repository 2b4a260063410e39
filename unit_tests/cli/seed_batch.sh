#!/usr/bin/env bash
# scripts/seed_batch.py flies a built-in and a file scenario in two other worlds: every run
# exits with 0 and gives its row, each written scenario carries the one seed in every part
# (a block map's own seed replaced, flow maps added), the worlds differ, and a source that
# is not a simulated flight is refused.
# Usage: seed_batch.sh LRSVO SOURCE_DIR OUT
set -uo pipefail
lrsvo=$1 source_dir=$2 out=$3
rm -rf "$out"
failed=0
fail() { echo "FAIL: $*" >&2; failed=1; }

table=$(python3 "$source_dir/scripts/seed_batch.py" --lrsvo "$lrsvo" --source sim:demo \
  --source "sim:$source_dir/sim/scenarios/gust.yaml" --seeds 2-3 --out "$out" -- --frames 4)
status=$?
printf '%s\n' "$table"
[ $status -eq 0 ] || fail "seed_batch.py exited with $status"
for row in "| demo | 2 |" "| demo | 3 |" "| gust | 2 |" "| gust | 3 |"; do
  grep -qF "$row" <<<"$table" || fail "no row '$row'"
done
grep -q "fails" <<<"$table" && fail "a run failed"

for scenario in "$out/demo_s3.yaml" "$out/gust_s3.yaml"; do
  seeds=$(grep -Eo "seed: [0-9]+" "$scenario" | sort | uniq -c)
  [ "$seeds" = "      5 seed: 3" ] || fail "$scenario: seeds are '$seeds', not five times 3"
done
grep -q "^  seed: 3$" "$out/gust_s3.yaml" || fail "the gust flight's block map has no seed 3"

# What the front end found in each world's images (features, tracks, stereo matches), not its times.
found() { [ -s "$1" ] && cut -d, -f6-9 "$1"; }
found2=$(found "$out/demo_s2/0/frames.csv") && found3=$(found "$out/demo_s3/0/frames.csv") ||
  fail "no frames.csv written"
[ "$found2" = "$found3" ] && fail "seeds 2 and 3 give the same images"

if python3 "$source_dir/scripts/seed_batch.py" --lrsvo "$lrsvo" --source "$source_dir" --seeds 1 \
  --out "$out/refused" >/dev/null 2>&1; then
  fail "a source that is not sim: was accepted"
fi
exit $failed
