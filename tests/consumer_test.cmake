# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the built project into a fresh prefix, then configures, builds and runs the consumer
# in examples/consumer (and builds examples/pipeline) against it with find_package(pcl_wrap): what
# a downstream user does. With STATIC, first builds the library alone as a static library (in
# WORK_DIR/static) and installs that instead. Without STATIC, also runs the installed command-line
# tool with no LD_LIBRARY_PATH: it finds the installed library by itself; with PYTHON (an
# interpreter), imports the installed Python package from the prefix and wraps with it.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed: ${ARGN}\n${out}")
  endif()
endfunction()
if(STATIC)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/static -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF
      -DPCL_WRAP_BUILD_APPS=OFF -DPCL_WRAP_BUILD_TESTS=OFF -DPCL_WRAP_BUILD_BENCH=OFF
      -DPCL_WRAP_BUILD_PYTHON=OFF)
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/static -j2)
  set(BUILD_DIR ${WORK_DIR}/static)
endif()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
file(GLOB_RECURSE archives ${WORK_DIR}/prefix/libpcl_wrap.a)
if(STATIC AND NOT archives)
  message(FATAL_ERROR "no static library installed")
endif()
if(NOT STATIC)
  file(WRITE ${WORK_DIR}/points.xyz "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n0.3 0.3 0.3\n")
  run(${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH ${WORK_DIR}/prefix/bin/pcl_wrap ${WORK_DIR}/points.xyz
      ${WORK_DIR}/points.ply --quiet)
  if(NOT EXISTS ${WORK_DIR}/points.ply)
    message(FATAL_ERROR "the installed pcl_wrap wrote no mesh")
  endif()
  # The installed pictures script finds its helpers and the installed tool.
  run(${WORK_DIR}/prefix/bin/pcl_wrap_render --help)
  file(GLOB helpers ${WORK_DIR}/prefix/share/pcl_wrap/scripts/view.sh ${WORK_DIR}/prefix/share/pcl_wrap/scripts/png_coverage.py)
  list(LENGTH helpers count)
  if(NOT count EQUAL 2)
    message(FATAL_ERROR "pcl_wrap_render's helpers are not installed: ${helpers}")
  endif()
endif()
if(PYTHON) # the installed Python package, from the prefix alone
  run(${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH PYTHONPATH=${WORK_DIR}/prefix/lib/python3/dist-packages
      PYTHONDONTWRITEBYTECODE=1 ${PYTHON} -c
      "import pcl_wrap; assert pcl_wrap.__file__.startswith('${WORK_DIR}/prefix'), pcl_wrap.__file__; \
r = pcl_wrap.wrap([[0,0,0],[1,0,0],[0,1,0],[0,0,1],[1,1,1]]); assert len(r.triangles) == 6, r")
endif()
if(EXISTS ${WORK_DIR}/prefix/include/pcl_wrap)
  file(GLOB_RECURSE headers ${WORK_DIR}/prefix/include/pcl_wrap/*)
  foreach(h ${headers})
    file(STRINGS ${h} cgal REGEX "#include <CGAL/")
    if(cgal)
      message(FATAL_ERROR "installed header ${h} includes CGAL")
    endif()
  endforeach()
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build -j2)
run(${WORK_DIR}/build/consumer)
# The PCL pipeline example builds the same way.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/pipeline -B ${WORK_DIR}/build-pipeline
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build-pipeline -j2)
# The README's own pipeline project, as written there, built and run on a coloured cloud.
if(NOT STATIC)
  run(/usr/bin/python3 ${SOURCE_DIR}/tests/readme_files.py ${SOURCE_DIR}/README.md ${WORK_DIR}/readme)
  run(${CMAKE_COMMAND} -S ${WORK_DIR}/readme -B ${WORK_DIR}/build-readme -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
      -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/build-readme -j2)
  set(pcd "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n")
  string(APPEND pcd "WIDTH 6\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 6\nDATA ascii\n")
  string(APPEND pcd "0 0 0 16711680\n1 0 0 65280\n0 1 0 255\n0 0 1 16711935\n1 1 1 65535\n0.3 0.3 0.3 8421504\n")
  file(WRITE ${WORK_DIR}/coloured.pcd "${pcd}")
  run(${WORK_DIR}/build-readme/my_pipeline ${WORK_DIR}/coloured.pcd ${WORK_DIR}/coloured.ply)
  # The README's first C++ snippet, a function, called on a regular tetrahedron: its four faces.
  file(WRITE ${WORK_DIR}/readme-cloud/CMakeLists.txt
       "cmake_minimum_required(VERSION 3.16)\nproject(readme_cloud LANGUAGES C CXX)\n"
       "find_package(pcl_wrap REQUIRED)\nadd_executable(readme_cloud main.cpp ${WORK_DIR}/readme/wrap_cloud.cpp)\n"
       "target_link_libraries(readme_cloud PRIVATE pcl_wrap::pcl_wrap)\n")
  file(WRITE ${WORK_DIR}/readme-cloud/main.cpp
       "#include <pcl/PolygonMesh.h>\n#include <pcl/pcl_base.h>\n#include <pcl/point_types.h>\n"
       "pcl::PolygonMesh wrapCloud (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr&, const pcl::IndicesConstPtr&);\n"
       "int main () {\n  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();\n"
       "  for (const auto& p : {pcl::PointXYZ (1, 1, 1), pcl::PointXYZ (1, -1, -1), pcl::PointXYZ (-1, 1, -1),\n"
       "                        pcl::PointXYZ (-1, -1, 1)}) cloud->push_back (p);\n"
       "  auto all = pcl::make_shared<pcl::Indices> (pcl::Indices {0, 1, 2, 3});\n"
       "  return wrapCloud (cloud, all).polygons.size () == 4 ? 0 : 1;\n}\n")
  run(${CMAKE_COMMAND} -S ${WORK_DIR}/readme-cloud -B ${WORK_DIR}/build-readme-cloud
      -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/build-readme-cloud -j2)
  run(${WORK_DIR}/build-readme-cloud/readme_cloud)
  if(PYTHON) # the README's Python example, with the installed package
    run(${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH PYTHONPATH=${WORK_DIR}/prefix/lib/python3/dist-packages
        PYTHONDONTWRITEBYTECODE=1 ${PYTHON} ${WORK_DIR}/readme/readme_example.py)
  endif()
  file(READ ${WORK_DIR}/coloured.ply header LIMIT 400)
  if(NOT header MATCHES "property uchar red" AND NOT header MATCHES "property float rgb")
    message(FATAL_ERROR "the README pipeline's PLY has no colours:\n${header}")
  endif()
endif()
message(STATUS "consumer, pipeline and the README's pipeline built against the installed package; they ran")
