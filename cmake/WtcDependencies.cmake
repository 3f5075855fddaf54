# Every dependency comes from a Debian 12 package and is found through CMake.
# The core needs only Eigen and Qhull; the engines, FCL and the test tools are
# needed by the plugins, the tests and the benchmarks.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Qhull REQUIRED CONFIG)

find_package(PkgConfig REQUIRED)
# The engine adapters (wtc::bullet, wtc::ode).
# Bullet ships float and double builds; WTC is double throughout. The .pc
# file adds -DBT_USE_DOUBLE_PRECISION; never link the float build as well.
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)
# ODE has no CMake config; Debian builds it with dDOUBLE.
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
if(WTC_BUILD_TESTS OR WTC_BUILD_BENCHMARKS)
  # libccd's .pc reports 2.0 for the 2.1 package: no version request.
  pkg_check_modules(CCD REQUIRED IMPORTED_TARGET ccd)
  # fcl.pc forces -std=c++11: use the CMake config (target `fcl`).
  find_package(fcl CONFIG REQUIRED)
endif()
if(WTC_BUILD_TESTS)
  find_package(GTest REQUIRED CONFIG)
endif()
if(WTC_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED CONFIG)
endif()

# wtc::io reads terrain files. Debian's assimp 5.2.5 package reports 5.2.4 in
# its CMake config: no version request. yaml-cpp's config defines the target
# `yaml-cpp` (no namespace) in 0.7.
find_package(assimp CONFIG REQUIRED)
find_package(yaml-cpp CONFIG REQUIRED)
