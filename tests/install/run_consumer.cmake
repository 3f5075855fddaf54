# Builds and runs one program against an installed WTC (install_package.cmake) as README.md tells a user:
# a project whose CMakeLists.txt is the README's cmake block marked for tests/install, verbatim, with the
# program as its source, configured with nothing but the package's prefix. Run by ctest as
#   cmake -DWTC_PREFIX=... -DWTC_README=... -DWTC_PROGRAM=... -DWTC_WORK_DIR=...
#         [-DWTC_GENERATOR=...] [-DWTC_MAKE_PROGRAM=...] [-DWTC_CXX_COMPILER=...]
#         -P run_consumer.cmake
# The generator, make program and compiler are this build's own (a package is built with and for one
# compiler); they set nothing in the project. Everything it writes is under WTC_WORK_DIR (in the build
# tree), which is wiped first so every run starts clean.
cmake_minimum_required(VERSION 3.25)

foreach(var WTC_PREFIX WTC_README WTC_PROGRAM WTC_WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: ${var} is not set")
  endif()
endforeach()

# Runs a command, failing the test with its output if it fails.
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err
    WORKING_DIRECTORY ${WTC_WORK_DIR})
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${step} failed (${result}):\n${out}\n${err}")
  endif()
  message(STATUS "${step}: ok\n${out}")
endfunction()

# The README's block: the first ```cmake fence after the line that names tests/install.
file(STRINGS ${WTC_README} lines)
set(state before)
set(block "")
foreach(line IN LISTS lines)
  if(state STREQUAL "before" AND line MATCHES "^<!-- tests/install builds every example")
    set(state marker)
  elseif(state STREQUAL "marker" AND line STREQUAL "```cmake")
    set(state inside)
  elseif(state STREQUAL "inside" AND line STREQUAL "```")
    set(state done)
    break()
  elseif(state STREQUAL "inside")
    string(APPEND block "${line}\n")
  endif()
endforeach()
if(NOT state STREQUAL "done")
  message(FATAL_ERROR "${WTC_README}: no ```cmake block after the line '<!-- tests/install builds every example'")
endif()
string(REGEX MATCH "add_executable\\(([A-Za-z0-9_]+) ([A-Za-z0-9_.]+)\\)" executable "${block}")
if(NOT executable)
  message(FATAL_ERROR "${WTC_README}: its project block has no add_executable(<name> <source>):\n${block}")
endif()
set(name ${CMAKE_MATCH_1})
set(source ${CMAKE_MATCH_2})

set(project ${WTC_WORK_DIR}/${name})
set(build ${project}/build)
file(REMOVE_RECURSE ${WTC_WORK_DIR})
file(MAKE_DIRECTORY ${project})
file(WRITE ${project}/CMakeLists.txt "${block}")
file(COPY_FILE ${WTC_PROGRAM} ${project}/${source})
message(STATUS "${project}/CMakeLists.txt (from ${WTC_README}):\n${block}")

include(${CMAKE_CURRENT_LIST_DIR}/consumer_configure.cmake)
wtc_consumer_configure_args(${project} ${build})
run("configure ${name}" ${CMAKE_COMMAND} ${consumer_configure_args})

# The package must have come from the scratch prefix, not from elsewhere.
file(STRINGS ${build}/CMakeCache.txt wtc_dir_line REGEX "^wtc_DIR:")
string(FIND "${wtc_dir_line}" "${WTC_PREFIX}/" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "the project found wtc outside ${WTC_PREFIX}: ${wtc_dir_line}")
endif()

run("build ${name}" ${CMAKE_COMMAND} --build ${build})
find_program(program ${name} PATHS ${build} ${build}/Release ${build}/Debug NO_DEFAULT_PATH NO_CACHE REQUIRED)
run("run ${name} (${WTC_PROGRAM})" ${program})
