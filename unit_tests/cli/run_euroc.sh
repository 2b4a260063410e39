#!/usr/bin/env bash
# `lrsvo run` on the real EuRoC frames (a room, the vehicle nearly still: it
# moves about 2 mm in 4.7 s): exit status 0, at least 90 % of the frames posed
# (the stereo start needs no motion), and no pose farther than 1 cm from the
# first (an odometry must not invent motion the stereo rig cannot see).
# Exits 77 (skipped) without the data.
# Usage: run_euroc.sh LRSVO EUROC_DIR WORK_DIR
set -euo pipefail
lrsvo=$1
euroc=$2
out=$3
if [[ ! -d "$euroc/mav0" ]]; then
  echo "SKIP: no $euroc/mav0 (../shared/data is not beside the repository)"
  exit 77
fi
rm -rf "$out"
"$lrsvo" run "$euroc" --min-depth 0.5 --no-plot --quiet --out "$out"
python3 - "$out" <<'PY'
import json, math, sys
out = sys.argv[1]
metrics = json.load(open(f"{out}/metrics.json"))
frames, tracked = metrics["frames"], metrics["frames_tracked"]
assert frames == 95, f"{frames} frames, the sequence has 95"
assert tracked >= 0.9 * frames, f"{tracked} of {frames} frames posed, need 90 %"
poses = [list(map(float, line.split()[1:4])) for line in open(f"{out}/trajectory.tum") if not line.startswith("#")]
assert len(poses) == tracked + metrics["frames_predicted"], (len(poses), tracked)
farthest = max(math.dist(p, poses[0]) for p in poses)
assert farthest < 0.01, f"a pose {farthest * 1000:.1f} mm from the first (the vehicle moved ~2 mm)"
print(f"{tracked} of {frames} frames posed, farthest {farthest * 1000:.2f} mm from the first")
PY
