#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: run_ros_test.sh BUILD_DIR TEST_BINARY POINT_FILE
#
# Installs the build into a temporary prefix, starts a real roscore on a free port, the node in
# namespace /basic through the launch file (roslaunch finds it as an installed ROS package), the
# same in /launched with the launch file's arguments output:=raw radius_rel:=2 manifold:=true, the
# nodelet standalone in /tight with those as private parameters, and runs the client test. Then
# the command-line tools on the node's topics, the log line per cloud, and bad parameters: the
# node exits with 1 and says which, the nodelet says which and stays idle.
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
ROS_NAMESPACE=launched roslaunch --wait pcl_wrap wrap.launch output:=raw radius_rel:=2 manifold:=true \
  > "$work/launched.log" 2>&1 &
pids+=($!)
/usr/lib/nodelet/nodelet standalone pcl_wrap/WrapNodelet __ns:=tight __name:=pcl_wrap \
  _output:=raw _radius_rel:=2 _manifold:=true > "$work/nodelet.log" 2>&1 &
pids+=($!)

status=0
"$test_binary" "$data" || status=$?
fail() { echo "FAILED: $*"; status=1; }

# rostopic on the node's topics: the latched mesh and marker echo at once, a cloud published from
# the command line (a tetrahedron) comes back as a mesh in its frame.
timeout 30 rostopic echo -n 1 /basic/marker/type > "$work/echo.txt" 2>&1 || fail "rostopic echo /basic/marker"
grep -q "^11$" "$work/echo.txt" || fail "rostopic echo /basic/marker/type: $(cat "$work/echo.txt")"
timeout 5 rostopic hz /basic/marker > "$work/hz.txt" 2>&1 || true
grep -q "subscribed to \[/basic/marker\]" "$work/hz.txt" || fail "rostopic hz /basic/marker: $(cat "$work/hz.txt")"
points=$(python3 -c 'import struct; print(list(struct.pack("<12f", 0,0,0, 1,0,0, 0,1,0, 0,0,1)))')
fields='[{name: x, offset: 0, datatype: 7, count: 1}, {name: y, offset: 4, datatype: 7, count: 1}, {name: z, offset: 8, datatype: 7, count: 1}]'
timeout 30 rostopic pub -1 /basic/cloud sensor_msgs/PointCloud2 \
  "{header: {frame_id: from_rostopic}, height: 1, width: 4, fields: $fields, point_step: 12, row_step: 48, data: $points, is_dense: true}" \
  > "$work/pub.txt" 2>&1 || fail "rostopic pub: $(cat "$work/pub.txt")"
# The mesh is latched: the newest is the one from the command line, once the node has wrapped it.
for _ in $(seq 50); do
  timeout 10 rostopic echo -n 1 /basic/mesh/header/frame_id > "$work/frame.txt" 2>&1 || true
  grep -q from_rostopic "$work/frame.txt" && break
  sleep 0.2
done
grep -q from_rostopic "$work/frame.txt" || fail "no mesh for the cloud from rostopic pub: $(cat "$work/frame.txt")"

# One log line per cloud, in the ROS log (rosout).
grep -rEq "pcl_wrap: [0-9]+ points \([0-9]+ used, [0-9]+ off the surface\) -> [0-9]+ triangles in" "$work/log" || fail "no log line per cloud"

# Bad parameters: a clear message naming the parameter; the node exits with 1.
node="$work/prefix/lib/pcl_wrap/pcl_wrap_node"
for bad in "_mode:=Front|~mode must be front or global" "_radius_rel:=-1|~radius_rel must be a number > 0" \
           "_output:=mesh|~output must be surface, closed or raw" "_threads:=many|~threads must be" \
           "_manifold:=true|~manifold splits the raw W"; do
  args=${bad%%|*} message=${bad#*|}
  node_status=0
  timeout 60 "$node" __ns:=bad __name:=pcl_wrap "$args" > "$work/bad.log" 2>&1 || node_status=$?
  [ $node_status -eq 1 ] || fail "$args: exit status $node_status, not 1"
  grep -qF -- "$message" "$work/bad.log" || fail "$args: no message '$message' in: $(cat "$work/bad.log")"
  rosparam delete /bad > /dev/null 2>&1 || true
done
timeout 10 /usr/lib/nodelet/nodelet standalone pcl_wrap/WrapNodelet __ns:=badlet __name:=pcl_wrap _mode:=Front \
  > "$work/badlet.log" 2>&1 || true
grep -qF "~mode must be front or global" "$work/badlet.log" || fail "nodelet: no message in: $(cat "$work/badlet.log")"

if [ $status -ne 0 ]; then
  echo "--- ROS log"; find "$work/log" -name "rosout.log" -exec tail -20 {} \;
  echo "--- roslaunch"; cat "$work/launch.log"
  echo "--- roslaunch with arguments"; cat "$work/launched.log"
  echo "--- nodelet"; cat "$work/nodelet.log"
fi
exit $status
