# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the built project into a fresh prefix, then configures, builds and runs the consumer
# in examples/consumer (and builds examples/pipeline) against it with find_package(pcl_wrap): what a downstream user does.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed: ${ARGN}\n${out}")
  endif()
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
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
message(STATUS "consumer and pipeline built against the installed package; consumer ran")
