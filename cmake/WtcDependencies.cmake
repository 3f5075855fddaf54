# Every dependency comes from a Debian 12 package and is found through CMake.
# The core needs only Eigen and Qhull; FCL and the test tools are needed by
# the tests and the benchmarks.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Qhull REQUIRED CONFIG)

find_package(PkgConfig REQUIRED)
# Each engine finds what it needs in its own folder (plugins/<engine>/
# dependencies.cmake, through wtc_add_engine).
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
# DEMs (GeoTIFF and every raster GDAL reads): GDAL 3.6's own CMake config.
find_package(GDAL CONFIG REQUIRED)
# summary.json of a run (wtc::io), wtc-sim and wtc-study.
find_package(nlohmann_json 3 CONFIG REQUIRED)
# wtc::vehicle reads URDF files with urdfdom (its CMake config's targets
# urdfdom::urdfdom_model, which bring console_bridge and TinyXML, the XML
# parser urdfdom uses and the reader asks for the <link> elements' order).
find_package(urdfdom CONFIG REQUIRED)
# wtc::study runs a study's simulations on a TBB worker pool.
find_package(TBB CONFIG REQUIRED)

# A package's CMake config can name files that only another package installs:
# Debian's assimp config links /usr/lib/<arch>/libz.so, and libassimp-dev does
# not depend on zlib1g-dev. Say so here, by name, rather than as a make error
# ("No rule to make target .../libz.so") halfway through the build.
function(wtc_require_linked_files)
  foreach(target IN LISTS ARGN)
    if(NOT TARGET ${target})
      continue()
    endif()
    get_target_property(libs ${target} INTERFACE_LINK_LIBRARIES)
    string(REGEX MATCHALL "/[^;<>$]+" files "${libs}")
    foreach(file IN LISTS files)
      if(NOT EXISTS "${file}")
        message(FATAL_ERROR "${target}'s CMake config links ${file}, which is not "
          "installed; tools/install-deps.sh installs every package the build needs")
      endif()
    endforeach()
  endforeach()
endfunction()
wtc_require_linked_files(assimp::assimp yaml-cpp GDAL::GDAL urdfdom::urdfdom_model fcl Qhull::qhullcpp
  Qhull::qhull_r GTest::gtest GTest::gmock benchmark::benchmark)
