# wtc_add_engine(<name>
#                DEPENDENCIES <file>
#                PLUGIN_SOURCES <file>... [PLUGIN_LINKS <target>...]
#                [SIM_SOURCES <file>...])
#
# Declares one physics engine, once, from its own folder (plugins/<name>; the
# one line outside it is add_subdirectory(<name>) in plugins/CMakeLists.txt,
# before the engine table):
#  - what it needs: <file> finds it (find_package, pkg_check_modules with
#    IMPORTED_TARGET GLOBAL), included here for the build and installed
#    beside wtcConfig.cmake, which includes it for a program of one's own;
#  - its adapter, wtc::<name> (WTC wheels in the engine's own worlds: public
#    headers under include/wtc/<name>/, links wtc::core and PLUGIN_LINKS),
#    and its sim engine, wtc::<name>_sim (wtc::sim::Engine for whole
#    vehicles; no public headers), both through wtc_add_library, so both are
#    installed and exported; the engine's folder is both libraries' private
#    include root (#include "src/conversions.hpp");
#  - its entries in the engine table (wtc::sim_engines, plugins/engine_table):
#    the sim engine defines wtc::<name>::engineEntries() (src/sim/
#    engine_entry.hpp), and the table's generated source names it.
# Without SIM_SOURCES the engine is its adapter alone (an engine landing
# adapter first): no sim engine, no entry in the table (WTC_ADAPTERS, not
# WTC_ENGINES). Either way a tests/<name> folder, if there is one, is the
# engine's tests (tests/CMakeLists.txt adds it).
# cmake/layers.txt gives every engine folder of plugins/ the engines' layer.
function(wtc_add_engine name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "DEPENDENCIES" "PLUGIN_SOURCES;PLUGIN_LINKS;SIM_SOURCES")
  foreach(required IN ITEMS DEPENDENCIES PLUGIN_SOURCES)
    if(NOT arg_${required})
      message(FATAL_ERROR "wtc_add_engine(${name}): ${required} is required")
    endif()
  endforeach()
  get_property(declared GLOBAL PROPERTY WTC_ENGINES)
  get_property(adapters GLOBAL PROPERTY WTC_ADAPTERS)
  if(name IN_LIST declared OR name IN_LIST adapters)
    message(FATAL_ERROR "wtc_add_engine(${name}): the engine is declared twice")
  endif()

  get_filename_component(dependencies ${arg_DEPENDENCIES} ABSOLUTE)
  include(${dependencies})
  install(FILES ${dependencies} DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/wtc
    RENAME wtc_${name}_dependencies.cmake)

  wtc_add_library(wtc_${name} EXPORT ${name} INCLUDE ${CMAKE_CURRENT_SOURCE_DIR}/include ENGINE_HEADERS
    SOURCES ${arg_PLUGIN_SOURCES})
  target_link_libraries(wtc_${name} PUBLIC wtc::core ${arg_PLUGIN_LINKS})
  target_include_directories(wtc_${name} PRIVATE $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>)
  if(NOT arg_SIM_SOURCES)
    set_property(GLOBAL APPEND PROPERTY WTC_ADAPTERS ${name})
    return()
  endif()
  wtc_add_library(wtc_${name}_sim EXPORT ${name}_sim ENGINE_HEADERS SOURCES ${arg_SIM_SOURCES})
  target_link_libraries(wtc_${name}_sim PUBLIC wtc::sim wtc::${name})
  target_include_directories(wtc_${name}_sim PRIVATE $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>)

  set_property(GLOBAL APPEND PROPERTY WTC_ENGINES ${name})
endfunction()
