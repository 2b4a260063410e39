#!/usr/bin/env bash
# The installed Python package works on its own: `cmake --install` into a scratch
# prefix, then `import lrsvo` from that prefix alone (not the build tree) and one solve.
# Usage: check_installed.sh BUILD_DIR WORK_DIR PYTHON
set -euo pipefail
build_dir=$1 work_dir=$2 python=$3
prefix="$work_dir/prefix"
rm -rf "$prefix"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
cd "$work_dir"
PYTHONPATH="$prefix/lib/python3/dist-packages" "$python" - "$prefix" <<'PY'
import os
import sys

import lrsvo

prefix = os.path.realpath(sys.argv[1])
module = os.path.realpath(lrsvo._lrsvo.__file__)
assert module.startswith(prefix + os.sep), f"lrsvo was imported from {module}, not from {prefix}"
g = lrsvo.Graph()
g.add_vertex("POSE_SE2", 0, [0.0, 0.0, 0.0], fixed=True)
g.add_vertex("POSE_SE2", 1, [0.5, 0.2, 0.1])
g.add_edge("RELATIVE_POSE_SE2", [0, 1], measurement=[1.0, 0.0, 0.0])
summary = g.optimize("lm_cholmod")
# The stop on a relative step of 1e-8 leaves at most about that step to go on O(1) values.
offset = max(abs(a - b) for a, b in zip(g.estimate(1), [1.0, 0.0, 0.0]))
assert summary.converged and offset < 1e-7, summary.full_report()
print("installed lrsvo imported from", module, "and solved:", summary.brief_report())
PY
