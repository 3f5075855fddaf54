# Installs the library and a relocatable CMake package:
#   find_package(wtc CONFIG REQUIRED)  ->  wtc::core, wtc::vehicle, wtc::sim, wtc::io, wtc::bullet, wtc::ode,
#   wtc::bullet_sim, wtc::ode_sim, wtc::sim_engines, wtc::study
include(CMakePackageConfigHelpers)

install(TARGETS wtc_core EXPORT wtcTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# wtc::vehicle (descriptions, drives, hitch), wtc::sim (engine interface, run loop) and wtc::io (file readers).
install(TARGETS wtc_vehicle wtc_sim wtc_io EXPORT wtcTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The engine adapters.
# And the accuracy study (wtc::study), which needs every engine.
foreach(adapter IN ITEMS wtc_bullet wtc_ode wtc_bullet_sim wtc_ode_sim wtc_sim_engines wtc_study)
  if(TARGET ${adapter})
    install(TARGETS ${adapter} EXPORT wtcTargets
      ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
      LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
      RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
      INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()
install(DIRECTORY include/wtc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY plugins/bullet/include/wtc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(EXISTS ${PROJECT_SOURCE_DIR}/plugins/ode/include/wtc)
  install(DIRECTORY plugins/ode/include/wtc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
foreach(dir IN ITEMS plugins/bullet/sim/include/wtc plugins/ode/sim/include/wtc plugins/engines/include/wtc)
  install(DIRECTORY ${dir} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

set(WTC_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/wtc)
install(EXPORT wtcTargets NAMESPACE wtc:: DESTINATION ${WTC_CMAKE_DIR})
configure_package_config_file(cmake/wtcConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/wtcConfig.cmake INSTALL_DESTINATION ${WTC_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/wtcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/wtcConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/wtcConfigVersion.cmake DESTINATION ${WTC_CMAKE_DIR})
