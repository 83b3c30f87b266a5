#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: run_ros_test.sh BUILD_DIR TEST_BINARY POINT_FILE
#
# Installs the build into a temporary prefix, starts a real roscore on a free port, the node in
# namespace /basic through the launch file (roslaunch finds it as an installed ROS package), the
# nodelet standalone in /tight with ~output raw, ~radius_rel 2 and ~manifold, and runs the client test.
set -euo pipefail
build=$1 test_binary=$2 data=$3
work=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT

cmake --install "$build" --prefix "$work/prefix" > /dev/null
export ROS_PACKAGE_PATH="$work/prefix/share:/usr/share"
export CMAKE_PREFIX_PATH="$work/prefix${CMAKE_PREFIX_PATH:+:$CMAKE_PREFIX_PATH}"
export AMENT_PREFIX_PATH="$work/prefix${AMENT_PREFIX_PATH:+:$AMENT_PREFIX_PATH}"
export ROS_HOSTNAME=127.0.0.1 ROS_LOG_DIR="$work/log" ROS_HOME="$work/home"
port=$(( 20000 + RANDOM % 20000 ))
export ROS_MASTER_URI="http://127.0.0.1:$port"

roscore -p "$port" > "$work/roscore.log" 2>&1 &
pids+=($!)
for _ in $(seq 150); do
  rostopic list > /dev/null 2>&1 && break
  sleep 0.2
done
rostopic list > /dev/null || { echo "roscore did not come up:"; cat "$work/roscore.log"; exit 1; }

ROS_NAMESPACE=basic roslaunch --wait pcl_wrap wrap.launch > "$work/launch.log" 2>&1 &
pids+=($!)
/usr/lib/nodelet/nodelet standalone pcl_wrap/WrapNodelet __ns:=tight __name:=pcl_wrap \
  _output:=raw _radius_rel:=2 _manifold:=true > "$work/nodelet.log" 2>&1 &
pids+=($!)

status=0
"$test_binary" "$data" || status=$?
if [ $status -ne 0 ]; then
  echo "--- roslaunch"; cat "$work/launch.log"
  echo "--- nodelet"; cat "$work/nodelet.log"
fi
exit $status
