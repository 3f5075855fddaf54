# Installs a WTC build into a scratch prefix and builds and runs the consumer
# project against it. Run by ctest as
#   cmake -DWTC_BUILD_DIR=... -DWTC_CONSUMER_SOURCE_DIR=... -DWTC_WORK_DIR=...
#         [-DWTC_CONFIG=...] [-DWTC_GENERATOR=...] [-DWTC_MAKE_PROGRAM=...]
#         [-DWTC_CXX_COMPILER=...]
#         -P run_consumer.cmake
# Everything it writes is under WTC_WORK_DIR (in the build tree), which is
# wiped first so every run starts clean.
cmake_minimum_required(VERSION 3.25)

foreach(var WTC_BUILD_DIR WTC_CONSUMER_SOURCE_DIR WTC_WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT WTC_CONFIG)
  set(WTC_CONFIG Release)
endif()

set(prefix ${WTC_WORK_DIR}/prefix)
set(consumer_build ${WTC_WORK_DIR}/build)
file(REMOVE_RECURSE ${WTC_WORK_DIR})
file(MAKE_DIRECTORY ${WTC_WORK_DIR})

# Runs a command, failing the test with its output if it fails.
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${step} failed (${result}):\n${out}\n${err}")
  endif()
  message(STATUS "${step}: ok")
endfunction()

run("install" ${CMAKE_COMMAND} --install ${WTC_BUILD_DIR} --prefix ${prefix} --config ${WTC_CONFIG})

set(configure_args -S ${WTC_CONSUMER_SOURCE_DIR} -B ${consumer_build}
  -DCMAKE_BUILD_TYPE=${WTC_CONFIG}
  -DCMAKE_PREFIX_PATH=${prefix}
  # Only the scratch prefix may provide wtc: no user or system registry.
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
if(WTC_GENERATOR)
  list(APPEND configure_args -G ${WTC_GENERATOR})
endif()
if(WTC_MAKE_PROGRAM)
  list(APPEND configure_args -DCMAKE_MAKE_PROGRAM=${WTC_MAKE_PROGRAM})
endif()
if(WTC_CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${WTC_CXX_COMPILER})
endif()
run("configure consumer" ${CMAKE_COMMAND} ${configure_args})

# The package must have come from the scratch prefix, not from elsewhere.
file(STRINGS ${consumer_build}/CMakeCache.txt wtc_dir_line REGEX "^wtc_DIR:")
string(FIND "${wtc_dir_line}" "${prefix}/" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "the consumer found wtc outside ${prefix}: ${wtc_dir_line}")
endif()

run("build consumer" ${CMAKE_COMMAND} --build ${consumer_build} --config ${WTC_CONFIG})

find_program(consumer wtc_consumer PATHS ${consumer_build} ${consumer_build}/${WTC_CONFIG}
  NO_DEFAULT_PATH REQUIRED)
run("run consumer" ${consumer})
