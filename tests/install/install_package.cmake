# Installs a WTC build into a scratch prefix (wiped first) and checks what a consumer of the package relies
# on. Run by ctest as
#   cmake -DWTC_BUILD_DIR=... -DWTC_PREFIX=... [-DWTC_CONFIG=...] -P install_package.cmake
cmake_minimum_required(VERSION 3.25)

foreach(var WTC_BUILD_DIR WTC_PREFIX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_package.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT WTC_CONFIG)
  set(WTC_CONFIG Release)
endif()

file(REMOVE_RECURSE ${WTC_PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${WTC_BUILD_DIR} --prefix ${WTC_PREFIX} --config ${WTC_CONFIG}
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "install failed (${result}):\n${out}\n${err}")
endif()

# Every exported target carries the C++20 its headers need, so a consumer compiles them as C++20 whatever
# it sets itself.
file(GLOB_RECURSE targets_files ${WTC_PREFIX}/wtcTargets.cmake)
list(LENGTH targets_files found)
if(NOT found EQUAL 1)
  message(FATAL_ERROR "expected one wtcTargets.cmake under ${WTC_PREFIX}, found ${found}: ${targets_files}")
endif()
file(READ ${targets_files} text)
string(REGEX MATCHALL "add_library\\(wtc::[A-Za-z0-9_]+" added "${text}")
if(NOT added)
  message(FATAL_ERROR "${targets_files} defines no wtc:: target")
endif()
set(missing "")
foreach(line IN LISTS added)
  string(REPLACE "add_library(" "" target "${line}")
  string(REGEX MATCH "set_target_properties\\(${target} PROPERTIES[^)]*\\)" properties "${text}")
  if(NOT properties MATCHES "INTERFACE_COMPILE_FEATURES \"[^\"]*cxx_std_20")
    list(APPEND missing ${target})
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "exported targets without INTERFACE_COMPILE_FEATURES cxx_std_20 in ${targets_files}: "
    "${missing} (cmake/WtcInstall.cmake gives it to every exported target)")
endif()
list(LENGTH added count)
message(STATUS "${count} exported targets, each with cxx_std_20")

# The data the examples and the shipped scenes load, where wtc_DATA_DIR says.
foreach(file terrains/ledge.yaml terrains/rough_ground_heights.csv vehicles/six_wheel_robot.yaml
             scenes/robot_straight.yaml)
  if(NOT EXISTS ${WTC_PREFIX}/share/wtc/${file})
    message(FATAL_ERROR "not installed: share/wtc/${file}")
  endif()
endforeach()
message(STATUS "installed into ${WTC_PREFIX}")
