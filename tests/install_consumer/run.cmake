# The install_package test: install a built acst into a scratch prefix, then configure, build and
# run a downstream project (this directory) that finds it with find_package(acst).
#
# Usage: cmake -DBUILD_DIR=<acst build dir> [-DWORK_DIR=<scratch dir>] -P run.cmake
# The compilers, generator, build type and sanitizer setting are read from BUILD_DIR's cache, so
# the consumer is built the way the library was (an ASan library needs an ASan executable).
cmake_minimum_required(VERSION 3.20)

if(NOT BUILD_DIR OR NOT EXISTS "${BUILD_DIR}/CMakeCache.txt")
  message(FATAL_ERROR "install_package: pass -DBUILD_DIR=<a configured and built acst build directory>")
endif()
if(NOT WORK_DIR)
  set(WORK_DIR "${BUILD_DIR}/install_package")
endif()
set(consumer_source "${CMAKE_CURRENT_LIST_DIR}")
get_filename_component(repo_root "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer-build")
file(REMOVE_RECURSE "${WORK_DIR}")

load_cache("${BUILD_DIR}" READ_WITH_PREFIX lib_
  CMAKE_GENERATOR CMAKE_C_COMPILER CMAKE_CXX_COMPILER CMAKE_BUILD_TYPE ACST_SANITIZE)

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install_package: ${name} failed (${rc}):\n${out}")
  endif()
  message(STATUS "install_package: ${name}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# 1. Install.
run_step("cmake --install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
foreach(f include/acst.h include/acst/material.hpp)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install_package: ${f} is not installed")
  endif()
endforeach()

# 2. Configure and build the consumer against the installed tree only.
set(flags "")
if(lib_ACST_SANITIZE)
  set(link_flags -fsanitize=address,undefined)
  if(lib_CMAKE_C_COMPILER MATCHES "clang")
    # clang's C driver leaves out UBSan's C++ handlers, which the library calls (CMakeLists.txt).
    string(APPEND link_flags " -fsanitize-link-c++-runtime -lstdc++")
  endif()
  set(flags -DCMAKE_C_FLAGS=-fsanitize=address,undefined -DCMAKE_CXX_FLAGS=-fsanitize=address,undefined
            "-DCMAKE_EXE_LINKER_FLAGS=${link_flags}")
endif()
run_step("configure consumer" "${CMAKE_COMMAND}" -S "${consumer_source}" -B "${consumer_build}"
  -G "${lib_CMAKE_GENERATOR}" "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_BUILD_TYPE=${lib_CMAKE_BUILD_TYPE}"
  "-DCMAKE_C_COMPILER=${lib_CMAKE_C_COMPILER}" "-DCMAKE_CXX_COMPILER=${lib_CMAKE_CXX_COMPILER}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF ${flags})
load_cache("${consumer_build}" READ_WITH_PREFIX consumer_ acst_DIR)
file(REAL_PATH "${prefix}" real_prefix)
file(REAL_PATH "${consumer_acst_DIR}" real_acst_dir)
string(FIND "${real_acst_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "install_package: acst was found in '${consumer_acst_DIR}', not in the install prefix ${prefix}")
endif()
run_step("build consumer" "${CMAKE_COMMAND}" --build "${consumer_build}")

# 3. Run both consumers.
set(parameters "${repo_root}/data/parameters/toyoura_acst_guide.json")
foreach(exe consumer_c consumer_cxx)
  run_step("run ${exe}" "${consumer_build}/${exe}" "${parameters}")
  message(STATUS "${step_output}")
endforeach()
message(STATUS "install_package: passed")
