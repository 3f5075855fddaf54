# What wtc::ode needs, found alike in the build (wtc_add_engine) and in the installed package (wtcConfig.cmake
# includes this file as wtc_ode_dependencies.cmake). ODE has no CMake config; Debian builds it with dDOUBLE.
find_package(PkgConfig REQUIRED)
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET GLOBAL ode)
