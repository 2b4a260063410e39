#!/usr/bin/env bash
# Every plugin lrsvo ships is registered in the program, however it was linked (shared or
# static libraries): `lrsvo solvers` and `lrsvo study list` name each one.
# Usage: registries.sh LRSVO
set -uo pipefail
lrsvo=$1
failed=0
check() {  # check LISTING NAME...: each NAME is a word of LISTING
  local listing=$1
  shift
  for name in "$@"; do
    if ! grep -Eq "(^|[[:space:]])${name}([[:space:]]|$)" <<<"$listing"; then
      echo "FAIL: '$name' is not listed" >&2
      failed=1
    fi
  done
}
solvers=$("$lrsvo" solvers) || { echo "FAIL: lrsvo solvers exited with $?" >&2; exit 1; }
printf '%s\n' "$solvers"
check "$solvers" lm gn dense cholmod schur_dense schur_cholmod lm_schur_cholmod gn_dense \
  none log_barrier gradient_projection nlopt_lbfgs nlopt_mma Huber Cauchy Tukey \
  POSE_SE3 POINT3 STEREO_EXTRINSIC SCALE STEREO_EXTRINSIC_RATE BAL_CAMERA \
  PROJECT_BASE PROJECT_SECONDARY PROJECT_SECONDARY_SCALED PROJECT_SECONDARY_DRIFTING PROJECT_HELD_VIEW \
  SCALE_PRIOR CENTRE_DISTANCE STEREO_EXTRINSIC_RATE_PRIOR BAL_PROJECTION BOUND_BARRIER \
  POSE_SE2 POSE_SE3_QUAT RELATIVE_POSE_SE2 RELATIVE_POSE_SE3_QUAT VECTOR1 VECTOR9
studies=$("$lrsvo" study list) || { echo "FAIL: lrsvo study list exited with $?" >&2; exit 1; }
printf '%s\n' "$studies"
check "$studies" disparity epipolar triangulation range-bias depth-distribution init-altitude init-scale
exit $failed
