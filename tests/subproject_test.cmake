# SPDX-License-Identifier: GPL-3.0-or-later
# Configures a project that takes pcl_wrap in with add_subdirectory, as FetchContent does, and
# checks that of pcl_wrap's targets only the library is there.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/source)
file(WRITE ${WORK_DIR}/source/CMakeLists.txt "cmake_minimum_required(VERSION 3.16)
project(outer LANGUAGES CXX)
add_subdirectory(${SOURCE_DIR} pcl_wrap)
foreach(target pcl_wrap pcl_wrap_cli pcl_wrap_files bench_wrap test_pipeline pcl_wrap_test_support)
  if(TARGET \${target})
    message(STATUS \"has target \${target}\")
  endif()
endforeach()
")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/source -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring the outer project failed:\n${out}")
endif()
string(REGEX MATCHALL "has target [a-z_]+" targets "${out}")
if(NOT targets STREQUAL "has target pcl_wrap")
  message(FATAL_ERROR "expected only the library, found: ${targets}")
endif()
message(STATUS "as a subproject, pcl_wrap adds only its library")
