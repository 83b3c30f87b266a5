#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the Python package as a wheel in DIR (default dist/): the engine and libpcl_wrap inside,
# linked against the system's PCL, CGAL and TBB (scripts/setup.sh installs them). Offline: the
# build requirements (setuptools, wheel) are the system's, not fetched.
#   pip install dist/pcl_wrap-*.whl
set -euo pipefail
cd "$(dirname "$0")/.."
dist="$(realpath -m "${1:-dist}")"
scripts/setup.sh
python3 -m pip wheel --no-build-isolation --no-deps --wheel-dir "$dist" . > "$dist.log" 2>&1 || { tail -30 "$dist.log"; exit 1; }
ls "$dist"/pcl_wrap-*.whl
