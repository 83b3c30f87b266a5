#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs, from Debian's archive, every package that pcl_wrap's build, tests and demo need.
# Idempotent and non-interactive: does nothing when everything is already installed.
set -euo pipefail

PACKAGES=(
  build-essential cmake ccache pkg-config python3
  libpcl-dev libcgal-dev libgmp-dev libmpfr-dev libtbb-dev libeigen3-dev libboost-dev
  libgtest-dev mpi-default-dev mpi-default-bin  # MPI: Debian's VTK names it; pcl_wrap_mpi and its tests run it
  clang libclang-rt-dev llvm   # the sanitizer and fuzzing build (libFuzzer, ASan, UBSan)
  clang-format-14 git          # the format check of changed lines
  libcgal-demo   # sample data: the Stanford bunny, kitten, fandisk
  # The ROS1 node and its test against a real roscore (Debian's ROS packages)
  libroscpp-dev libnodeletlib-dev libnodeletlib-tools libsensor-msgs-dev libpcl-conversions-dev
  libpcl-msgs-dev libvisualization-msgs-dev python3-roslaunch python3-rostopic rosout catkin
  python3-catkin-pkg
  # rostopic echo/hz/pub on the node's topics: the messages' Python modules
  python3-sensor-msgs python3-pcl-msgs python3-visualization-msgs python3-std-msgs python3-geometry-msgs
  # Pictures: pcl_viewer and an X server without a display
  pcl-tools xvfb xauth xdotool python3-pil
  # The benchmark's peers from Python (Open3D's ball pivoting and alpha shape) and its plots
  python3-open3d python3-matplotlib python3-scipy
  # The Python package, and pip-installing it into a virtual environment
  python3-dev pybind11-dev python3-numpy python3-venv python3-pip python3-setuptools python3-wheel
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq "${missing[@]}" > /dev/null
