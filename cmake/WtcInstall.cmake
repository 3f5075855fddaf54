# Installs the library and a relocatable CMake package:
#   find_package(wtc CONFIG REQUIRED)  ->  every library declared with wtc_add_library (wtc::core, wtc::vehicle,
#   wtc::sim, wtc::io, each engine's wtc::<engine> and wtc::<engine>_sim, wtc::sim_engines, wtc::study), and
#   wtc_DATA_DIR (the terrains, vehicles and scenes). What a user writes to use it: README.md, "Using the library";
#   tests/install builds every example so.
include(CMakePackageConfigHelpers)

# Every library declared with wtc_add_library (cmake/WtcLibrary.cmake), with the C++20 its headers need carried
# to its consumers (without it a consumer that sets no standard gets GCC 12's default, C++17, and dozens of
# errors: issue 35, row 2), and its public headers.
get_property(WTC_EXPORTED_TARGETS GLOBAL PROPERTY WTC_LIBRARIES)
install(TARGETS ${WTC_EXPORTED_TARGETS} EXPORT wtcTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
get_property(WTC_INCLUDE_DIRS GLOBAL PROPERTY WTC_PUBLIC_INCLUDE_DIRS)
list(REMOVE_DUPLICATES WTC_INCLUDE_DIRS)
foreach(dir IN LISTS WTC_INCLUDE_DIRS)
  install(DIRECTORY ${dir}/wtc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

# The terrains, vehicles and scenes (the examples load terrains/ledge.yaml; scenes name their terrain and
# vehicle by relative paths, which this layout keeps), beside wtc-sim's own files.
set(WTC_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/wtc)
install(DIRECTORY terrains vehicles scenes DESTINATION ${WTC_DATA_INSTALL_DIR})

# What each engine needs, found by the file it declared (wtc_add_engine installs it beside the config).
set(WTC_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/wtc)
get_property(engines GLOBAL PROPERTY WTC_ENGINES)
set(WTC_ENGINE_DEPENDENCIES "")
foreach(engine IN LISTS engines)
  string(APPEND WTC_ENGINE_DEPENDENCIES
    "include(\"\${CMAKE_CURRENT_LIST_DIR}/wtc_${engine}_dependencies.cmake\")  # wtc::${engine}\n")
endforeach()

install(EXPORT wtcTargets NAMESPACE wtc:: DESTINATION ${WTC_CMAKE_DIR})
configure_package_config_file(cmake/wtcConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/wtcConfig.cmake INSTALL_DESTINATION ${WTC_CMAKE_DIR}
  PATH_VARS WTC_DATA_INSTALL_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/wtcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/wtcConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/wtcConfigVersion.cmake DESTINATION ${WTC_CMAKE_DIR})
