# Installs the build into a fresh prefix and builds and runs examples/consumer against it:
# find_package(mkbool) and mkbool::mkbool work for another project (issue 3, library).
# Preconditions: run by ctest after a full build (cmake -P with the MK_* variables below).
foreach(var MK_BUILD_DIR MK_SOURCE_DIR MK_WORK_DIR MK_GENERATOR MK_CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "package_consumer.cmake: ${var} is not set")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${MK_WORK_DIR}/prefix)
file(REMOVE_RECURSE ${MK_WORK_DIR})
run_step("cmake --install" ${CMAKE_COMMAND} --install ${MK_BUILD_DIR} --prefix ${prefix})
foreach(installed
    include/mkbool/api/mkbool.hpp include/mkbool/core/polygon.hpp include/mkbool/io/wkt.hpp
    include/mkbool/arithmetic/kernels/exact_kernel.hpp bin/mkbool)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "not installed: ${installed}")
  endif()
endforeach()

set(build_type ${MK_BUILD_TYPE})
if(build_type STREQUAL "")
  set(build_type Release)
endif()
# Only the prefix is searched, so the test sees what a user of the installed package sees
# (not the build tree nor a package registry).
run_step("configuring examples/consumer" ${CMAKE_COMMAND}
  -S ${MK_SOURCE_DIR}/examples/consumer -B ${MK_WORK_DIR}/build -G ${MK_GENERATOR}
  -DCMAKE_CXX_COMPILER=${MK_CXX_COMPILER} -DCMAKE_BUILD_TYPE=${build_type}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_EXE_LINKER_FLAGS=${MK_LINK_FLAGS})
run_step("building examples/consumer" ${CMAKE_COMMAND} --build ${MK_WORK_DIR}/build)
run_step("running the consumer" ${MK_WORK_DIR}/build/consumer)
set(expected "island, 6 vertices\narea 3\n")
if(NOT step_output STREQUAL expected)
  message(FATAL_ERROR "consumer printed:\n${step_output}\nexpected:\n${expected}")
endif()
message(STATUS "consumer output:\n${step_output}")

# The readers and writers are part of the package too.
file(WRITE ${MK_WORK_DIR}/io/CMakeLists.txt [=[
cmake_minimum_required(VERSION 3.22)
project(mkbool_io_consumer LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
find_package(mkbool REQUIRED COMPONENTS io)
add_executable(io_consumer main.cpp)
target_link_libraries(io_consumer PRIVATE mkbool::mkbool mkbool::mkbool_io)
]=])
file(WRITE ${MK_WORK_DIR}/io/main.cpp [=[
#include <cstdio>
#include "api/mkbool.hpp"
#include "io/wkt.hpp"
int main() {
  const mk::Polygon a = mk::to_polygon(mk::read_wkt("POLYGON((0 0,2 0,2 2,0 2,0 0))"));
  const mk::Polygon b = mk::to_polygon(mk::read_wkt("POLYGON((1 1,3 1,3 3,1 3,1 1))"));
  std::printf("%s\n", mk::write_wkt(mk::compute(a, b, {}).output).c_str());
}
]=])
run_step("configuring the io consumer" ${CMAKE_COMMAND}
  -S ${MK_WORK_DIR}/io -B ${MK_WORK_DIR}/io-build -G ${MK_GENERATOR}
  -DCMAKE_CXX_COMPILER=${MK_CXX_COMPILER} -DCMAKE_BUILD_TYPE=${build_type}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_EXE_LINKER_FLAGS=${MK_LINK_FLAGS})
run_step("building the io consumer" ${CMAKE_COMMAND} --build ${MK_WORK_DIR}/io-build)
run_step("running the io consumer" ${MK_WORK_DIR}/io-build/io_consumer)
if(NOT step_output STREQUAL "POLYGON ((2 1, 2 2, 1 2, 1 1, 2 1))\n")
  message(FATAL_ERROR "io consumer printed:\n${step_output}")
endif()
file(REMOVE_RECURSE ${MK_WORK_DIR})
