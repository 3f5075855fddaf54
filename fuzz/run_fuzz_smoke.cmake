# ctest -L fuzz: configures and builds the fuzz targets with clang in
# BUILD_DIR, then runs each for RUNS inputs from seed 1 (the same inputs on
# every machine, so a red suite means a real change, not a lucky draw;
# SECONDS bounds a slow machine) on a scratch copy of its seed corpus
# (fuzz/corpus/<target>); any crash, sanitizer report, leak or input that
# runs longer than 10 s (a hang) fails the test.
#   cmake -DSOURCE_DIR=<repo> -DBUILD_DIR=<dir> -DCLANGXX=<clang++> -DRUNS=<n> -DSECONDS=<s> -P run_fuzz_smoke.cmake
set(targets point_query terrain vehicle scene mesh_off mesh_ply mesh_stl mesh_obj)
# -O1 with line tables only (as OSS-Fuzz builds): reports keep file and line,
# the build takes about half RelWithDebInfo's time.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/fuzz -B ${BUILD_DIR} -DCMAKE_CXX_COMPILER=${CLANGXX}
                        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG"
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the fuzz build failed (${rc})")
endif()
set(names)
foreach(t IN LISTS targets)
  list(APPEND names wtc_fuzz_${t})
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} -j2 --target ${names} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the fuzz targets failed (${rc})")
endif()
file(GLOB old_crashes ${BUILD_DIR}/crash-*)
if(old_crashes)
  file(REMOVE ${old_crashes})
endif()
# Leaks inside libassimp's own readers (not WTC's code) are suppressed, as
# in the sanitized suite.
set(ENV{LSAN_OPTIONS} "suppressions=${SOURCE_DIR}/tests/sanitizer_suppressions.txt:print_suppressions=0")
foreach(t IN LISTS targets)
  set(scratch ${BUILD_DIR}/corpus/${t})
  file(REMOVE_RECURSE ${scratch})
  file(MAKE_DIRECTORY ${scratch})
  message(STATUS "fuzzing ${t} for ${SECONDS} s")
  # New inputs go to the scratch directory (first), the seeds are only read.
  execute_process(COMMAND ${BUILD_DIR}/wtc_fuzz_${t} -seed=1 -runs=${RUNS} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048
                          -artifact_prefix=${BUILD_DIR}/crash-${t}- ${scratch} ${SOURCE_DIR}/fuzz/corpus/${t}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc)
    message(FATAL_ERROR "wtc_fuzz_${t} found a crash (exit ${rc}); the input is ${BUILD_DIR}/crash-${t}-*\n${out}")
  endif()
endforeach()
