#!/usr/bin/env bash
# `lrsvo eval` on ORB-SLAM2's published KITTI 00 trajectory against the truth:
# exit status 0, and metrics.json holding the published figures (Mur-Artal &
# Tardos 2017, Table 2: t_rel 0.70 %, r_rel 0.25 deg/100 m, ATE 1.3 m, each to
# half a unit of its last printed digit) and evo_rpe's over 10 m (0.2263 m over
# 353 pairs, printed to 4 digits). Exits 77 (skipped) without the data.
# Usage: eval_kitti00.sh LRSVO KITTI00_DIR WORK_DIR
set -euo pipefail
lrsvo=$1
data=$2
out=$3
if [[ ! -f "$data/KITTI_00_gt.txt" ]]; then
  echo "SKIP: no $data/KITTI_00_gt.txt (../shared/data is not beside the repository)"
  exit 77
fi
rm -rf "$out"
"$lrsvo" eval "$data/KITTI_00_ORB.txt" "$data/KITTI_00_gt.txt" --times "$data/KITTI_00_gt_times.txt" \
  --delta-m 10 --no-plot --out "$out"
python3 - "$out/metrics.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
def near(key, expected, half_unit):
    value = m[key]
    assert abs(value - expected) <= half_unit, f"{key} = {value}, expected {expected} +- {half_unit}"
    print(f"{key} {value:.6g} (expected {expected})")
near("drift_percent", 0.70, 0.005)
near("drift_deg_per_100m", 0.25, 0.005)
near("ate_rmse_m", 1.3, 0.05)
near("rpe_distance_trans_rmse_m", 0.2263, 0.00005)
assert m["rpe_distance_pairs"] == 353, f"{m['rpe_distance_pairs']} pairs over 10 m, evo takes 353"
PY
