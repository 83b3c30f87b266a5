#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""usage: package_xml_check.py package.xml

package.xml as catkin (ROS 1) and ament (ROS 2) read it: catkin_pkg's parser and validation
(both build tools use it), the dependencies each ROS version sees, and the exports."""
import sys

from catkin_pkg.package import parse_package

package = parse_package(sys.argv[1])
package.validate()
assert package.name == "pcl_wrap" and package.package_format == 3, package
exports = {e.tagname: e for e in package.exports}
assert exports["build_type"].content == "cmake", "plain CMake for both catkin_make_isolated/catkin tools and colcon"
assert "nodelet_plugins.xml" in exports["nodelet"].attributes["plugin"]
seen = {}
for version in ("1", "2"):
    package.evaluate_conditions({"ROS_VERSION": version})
    seen[version] = {d.name for d in package.build_depends + package.exec_depends if d.evaluated_condition}
assert {"roscpp", "nodelet", "pcl_conversions"} <= seen["1"], seen["1"]
assert not {"roscpp", "nodelet"} & seen["2"], seen["2"]
assert {"libpcl-all-dev", "libcgal-dev", "tbb"} <= seen["2"], seen["2"]
print(f"{sys.argv[1]}: valid format {package.package_format}; ROS 1 depends on {sorted(seen['1'])}")
