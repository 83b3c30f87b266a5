#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: pip_install_test.sh SOURCE_DIR
#
# The Python package as a user installs it: `pip install` of the repository into a fresh virtual
# environment (system site packages for NumPy and Open3D; no network, so the build requirements
# are the system's too), and the wheel that scripts/python-wheel.sh builds into another. Each is
# imported from outside the source tree and wraps a cloud.
set -euo pipefail
src=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

check() { # python: the package is the installed one, typed, versioned, and it works
  "$1" - "$2" <<'PY'
import os, sys
import numpy as np
import pcl_wrap
root = sys.argv[1]
assert pcl_wrap.__file__.startswith(root), (pcl_wrap.__file__, root)
here = os.path.dirname(pcl_wrap.__file__)
for typed in ("py.typed", "_core.pyi"):
    assert os.path.exists(os.path.join(here, typed)), typed
assert pcl_wrap.__version__.count(".") == 2, pcl_wrap.__version__
p = np.random.default_rng(0).normal(size=(2000, 3))
result = pcl_wrap.wrap(p / np.linalg.norm(p, axis=1)[:, None], colors=np.full((2000, 3), 0.5))
assert len(result.triangles) == 2 * 2000 - 4, len(result.triangles)
assert result.statistics["spacing"] > 0
print("ok", pcl_wrap.__version__, pcl_wrap.__file__)
PY
}

python3 -m venv --system-site-packages "$work/venv"
"$work/venv/bin/pip" install --no-build-isolation --no-deps "$src" > "$work/pip.log" 2>&1 || { tail -40 "$work/pip.log"; exit 1; }
check "$work/venv/bin/python" "$work/venv"

"$src/scripts/python-wheel.sh" "$work/dist" > /dev/null
python3 -m venv --system-site-packages "$work/wheel-venv"
"$work/wheel-venv/bin/pip" install --no-deps "$work"/dist/pcl_wrap-*.whl > "$work/wheel.log" 2>&1 || { tail -40 "$work/wheel.log"; exit 1; }
check "$work/wheel-venv/bin/python" "$work/wheel-venv"
