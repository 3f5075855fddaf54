# wtc_add_library(<target> EXPORT <name> [INCLUDE <dir>] [ENGINE_HEADERS] SOURCES <file>...)
#
# One of WTC's libraries, declared the same way for every layer: the alias
# wtc::<name> (what users and the other libraries link), its public headers
# under <dir>/wtc (default: the project's include/), the C++ standard its
# headers need carried to every consumer, the project's warnings, and the
# project's private headers (src/<stage>/*.hpp, never installed) for its
# own sources only. Every library declared so is installed and exported
# (cmake/WtcInstall.cmake reads the global properties WTC_LIBRARIES and
# WTC_PUBLIC_INCLUDE_DIRS). The layers and their order: cmake/layers.txt.
add_library(wtc_private_headers INTERFACE)
target_include_directories(wtc_private_headers INTERFACE ${PROJECT_SOURCE_DIR}/src)

function(wtc_add_library target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "ENGINE_HEADERS" "EXPORT;INCLUDE" "SOURCES")
  if(NOT arg_EXPORT)
    message(FATAL_ERROR "wtc_add_library(${target}): EXPORT <name> is required")
  endif()
  if(NOT arg_INCLUDE)
    set(arg_INCLUDE ${PROJECT_SOURCE_DIR}/include)
  endif()
  add_library(${target} ${arg_SOURCES})
  add_library(wtc::${arg_EXPORT} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${arg_EXPORT} OUTPUT_NAME ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${arg_INCLUDE}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:wtc_private_headers>)
  set_property(GLOBAL APPEND PROPERTY WTC_LIBRARIES ${target})
  set_property(GLOBAL APPEND PROPERTY WTC_PUBLIC_INCLUDE_DIRS ${arg_INCLUDE})
  # An engine's own headers (Bullet's, ODE's) are not -Wpedantic clean.
  if(arg_ENGINE_HEADERS)
    target_compile_options(${target} PRIVATE -Wall -Wextra)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  endif()
endfunction()

# Writes every target's direct link dependencies among the build's own
# targets, aliases resolved, to <build>/wtc_links.txt ('<target>: a;b;...'),
# for tools/check_layers.py (the test architecture.layers_look_only_down).
function(wtc_write_link_graph)
  set(dirs ${PROJECT_SOURCE_DIR})
  set(lines "")
  while(dirs)
    list(POP_FRONT dirs dir)
    get_property(sub DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    list(APPEND dirs ${sub})
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(t IN LISTS targets)
      get_target_property(type ${t} TYPE)
      if(type STREQUAL "UTILITY")
        continue()
      endif()
      get_target_property(libs ${t} LINK_LIBRARIES)
      if(NOT libs)
        set(libs "")
      endif()
      set(deps "")
      foreach(lib IN LISTS libs)
        string(REGEX REPLACE "^\\$<(BUILD_INTERFACE|LINK_ONLY):(.*)>$" "\\2" lib "${lib}")
        if(TARGET ${lib})
          get_target_property(aliased ${lib} ALIASED_TARGET)
          if(aliased)
            set(lib ${aliased})
          endif()
          list(APPEND deps ${lib})
        endif()
      endforeach()
      string(APPEND lines "${t}: ${deps}\n")
    endforeach()
  endwhile()
  file(WRITE ${CMAKE_BINARY_DIR}/wtc_links.txt "${lines}")
endfunction()
