# Installs the library and a relocatable CMake package:
#   find_package(wtc CONFIG REQUIRED)  ->  wtc::core, wtc::vehicle, wtc::sim, wtc::io, wtc::bullet, wtc::ode,
#   wtc::bullet_sim, wtc::ode_sim, wtc::sim_engines, wtc::study, and wtc_DATA_DIR (the terrains, vehicles and
#   scenes). What a user writes to use it: README.md, "Using the library"; tests/install builds every example so.
include(CMakePackageConfigHelpers)

# wtc::core; wtc::vehicle (descriptions, drives, hitch), wtc::sim (engine interface, run loop) and wtc::io (file
# readers); the engine adapters; and the accuracy study (wtc::study), which needs every engine.
set(WTC_EXPORTED_TARGETS wtc_core wtc_vehicle wtc_sim wtc_io)
foreach(target IN ITEMS wtc_bullet wtc_ode wtc_bullet_sim wtc_ode_sim wtc_sim_engines wtc_study)
  if(TARGET ${target})
    list(APPEND WTC_EXPORTED_TARGETS ${target})
  endif()
endforeach()
foreach(target IN LISTS WTC_EXPORTED_TARGETS)
  # Their headers are C++20 (std::span, defaulted operator==): every target that links one compiles as C++20
  # at least, whatever its own project sets. Without this a consumer that sets no standard gets GCC 12's
  # default (C++17) and dozens of errors (issue 35, row 2).
  target_compile_features(${target} PUBLIC cxx_std_20)
endforeach()
install(TARGETS ${WTC_EXPORTED_TARGETS} EXPORT wtcTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/wtc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY plugins/bullet/include/wtc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(EXISTS ${PROJECT_SOURCE_DIR}/plugins/ode/include/wtc)
  install(DIRECTORY plugins/ode/include/wtc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
foreach(dir IN ITEMS plugins/bullet/sim/include/wtc plugins/ode/sim/include/wtc plugins/engines/include/wtc)
  install(DIRECTORY ${dir} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

# The terrains, vehicles and scenes (the examples load terrains/ledge.yaml; scenes name their terrain and
# vehicle by relative paths, which this layout keeps), beside wtc-sim's own files.
set(WTC_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/wtc)
install(DIRECTORY terrains vehicles scenes DESTINATION ${WTC_DATA_INSTALL_DIR})

set(WTC_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/wtc)
install(EXPORT wtcTargets NAMESPACE wtc:: DESTINATION ${WTC_CMAKE_DIR})
configure_package_config_file(cmake/wtcConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/wtcConfig.cmake INSTALL_DESTINATION ${WTC_CMAKE_DIR}
  PATH_VARS WTC_DATA_INSTALL_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/wtcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/wtcConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/wtcConfigVersion.cmake DESTINATION ${WTC_CMAKE_DIR})
