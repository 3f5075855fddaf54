# Every installed header compiles alone: one translation unit per header under <prefix>/include/wtc, each
# including that header and nothing else, built against the installed package (install_package.cmake) in
# a project that links every exported library and sets nothing else (no standard, no definitions). A
# header that leans on another it does not include, or on a private header, fails here. Run by ctest as
#   cmake -DWTC_PREFIX=... -DWTC_WORK_DIR=... [-DWTC_GENERATOR=...] [-DWTC_MAKE_PROGRAM=...]
#         [-DWTC_CXX_COMPILER=...] -P headers_alone.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var WTC_PREFIX WTC_WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "headers_alone.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE ${WTC_WORK_DIR})
file(MAKE_DIRECTORY ${WTC_WORK_DIR}/src)
file(GLOB_RECURSE headers RELATIVE ${WTC_PREFIX}/include ${WTC_PREFIX}/include/wtc/*.hpp)
list(LENGTH headers count)
if(count LESS 40)
  message(FATAL_ERROR "only ${count} headers under ${WTC_PREFIX}/include/wtc: is the package installed?")
endif()
set(sources "")
foreach(header IN LISTS headers)
  string(MAKE_C_IDENTIFIER ${header} name)
  file(WRITE ${WTC_WORK_DIR}/src/${name}.cpp "#include <${header}>\n")
  list(APPEND sources src/${name}.cpp)
endforeach()
list(JOIN sources "\n  " source_lines)
file(WRITE ${WTC_WORK_DIR}/CMakeLists.txt "cmake_minimum_required(VERSION 3.25)
project(wtc_headers_alone LANGUAGES CXX)
find_package(wtc CONFIG REQUIRED)
add_library(headers OBJECT
  ${source_lines})
target_link_libraries(headers PRIVATE wtc::study wtc::sim_engines wtc::bullet_sim wtc::ode_sim)
")

include(${CMAKE_CURRENT_LIST_DIR}/consumer_configure.cmake)
wtc_consumer_configure_args(${WTC_WORK_DIR} ${WTC_WORK_DIR}/build)
execute_process(COMMAND ${CMAKE_COMMAND} ${consumer_configure_args} RESULT_VARIABLE result OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "configuring the headers' project failed (${result}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WTC_WORK_DIR}/build -j2 -- -k RESULT_VARIABLE result
  OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "some installed headers do not compile alone (${result}):\n${out}\n${err}")
endif()
message(STATUS "${count} installed headers compile alone")
