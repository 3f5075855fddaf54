# ctest -L sanitizers: the test suite built with AddressSanitizer and
# UndefinedBehaviorSanitizer (GCC) in BUILD_DIR, then run there. UBSan's
# reports abort (-fno-sanitize-recover=all) and ASan's and LeakSanitizer's
# fail their test, so any report fails this one. Leaks inside libassimp
# itself (outside WTC's code) are suppressed: tests/sanitizer_suppressions.txt.
# The Python package stays out (-DWTC_BUILD_PYTHON=OFF): Debian's python3 is
# not built with ASan, and an interpreter cannot load an instrumented module
# unless the ASan runtime is preloaded ("ASan runtime does not come first in
# initial library list"); the library code the package calls is in this suite.
# The build is -O1 -g1 (line tables), not RelWithDebInfo's -O2 -g: each
# report still names file and line, and the tree compiles in about half the
# time (a test file 33.6 s -> 17.8 s, a library file 11.8 s -> 6.8 s with
# GCC 12), which is what keeps the suite within CI's budget on two cores.
# The test files themselves are built with ASan only and no debug
# information (tests/CMakeLists.txt, WTC_SANITIZED_CHILD). Every target is
# a unity build here, as in the main build by default
# (cmake/WtcUnityBuild.cmake): a translation unit per batch of 8 files
# compiles the headers they share once (docs/development.md measures it).
# The flag is the default's; it is named here so that this build stays
# unity whatever the default becomes.
#   cmake -DSOURCE_DIR=<repo> -DBUILD_DIR=<dir> -DCXX=<g++> -P run_sanitized_suite.cmake
set(flags "-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BUILD_DIR} -DCMAKE_CXX_COMPILER=${CXX}
                        -DCMAKE_BUILD_TYPE=RelWithDebInfo
                        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS=${flags}
                        -DCMAKE_EXE_LINKER_FLAGS=${flags} -DCMAKE_SHARED_LINKER_FLAGS=${flags}
                        -DWTC_BUILD_BENCHMARKS=OFF -DWTC_BUILD_PYTHON=OFF -DWTC_SANITIZED_CHILD=ON
                        -DCMAKE_UNITY_BUILD=ON
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the sanitized build failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} -j2 RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the sanitized suite failed (${rc})")
endif()
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0:halt_on_error=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
set(ENV{LSAN_OPTIONS} "suppressions=${SOURCE_DIR}/tests/sanitizer_suppressions.txt:print_suppressions=0")
# What the sanitizers can find is found by one pass through the code: the
# tests that only run the same code longer (whole shipped scenes in every
# engine and mode, long holds, rate sweeps, a real Slurm around wtc-sim)
# stay out of this run; shorter tests of the same code stay in (the
# shipped scenes' short runs in VehicleScenesTest's other tests, the tilt
# table's single runs, the parked wheel at every step in HardCasesTest's
# other parking tests; the towed system's steady pull and incline for its
# S-curve and lowest-friction runs; the ledge climb's step out of reach for
# its climbs of two and of four heights; the event scenes' turn in place for the skid steer's at
# every step; the rover driving straight for its climb; GroundMemoryTest's
# ruts stepped without an engine for the test bed's ruts in both engines;
# SoilDynamicsTest's carriage and the skid-steered cart on sand for the test
# bed's twelve runs; SoilVehiclesTest's start on a scene's ruts for the
# second rover driving in them; HardCasesTest's driven run over the rough
# ground for Bullet's and ODE's whole runs of it; UrdfVehicleFileTest's
# towed system read from URDF equal to the YAML one, and the robot's URDF
# series, for the towed system's URDF series; BallSoilTest's ball caster
# stepped on ground that remembers, and the soil scenes' starts, for the
# towed system's stall on loam in both engines).
# Each of these ran
# 5-45 s unsanitized, several times that here (the last three 41-44 s each
# on two cores, 2026-11-30). The replay page's tests
# (label page) stay out too: chromium runs the page's JavaScript, which the
# sanitizers do not see; the replay files they load are written by every
# wtc-sim run of the suite.
set(long_runs "VehicleScenesTest.EveryShippedSceneRunsShortenedInEveryEngineWithoutNaN"
              "EnergyBalanceTest.ShippedScenesPassBothChecksInEveryEngineAndMode"
              "RoverScenesTest.CrossesRoughGroundWithItsDifferentialHeldInBothEnginesAndModes"
              "TowedSystemTest.AtItsEndThePathStopsTheTugAndSoDoesALostPath"
              "StepCountTest.EveryShippedSceneAndStudyRunKeepsItsStepCount"
              "TiltTableTest.HalvingTheTiltRateMovesTheAnswerByLessThanATenthOfADegree"
              "HardCasesTest.AParkedWheelHoldsForAnHourOn15And30Degrees"
              "TowedSystemTest.TracksAStraightLineAndAGentleSCurveOnFlatGround"
              "TowedSystemTest.LowestFrictionCaseFailsAndSaysSo"
              "LedgeClimbTest.ClimbsTwoHeightsInBothEnginesAndMeasuresEachStep"
              "LedgeClimbTest.EveryEngineClimbsEveryHeightFrom20To60Centimetres"
              "LedgeClimbTest.EveryEngineClimbsTheLedgeSampledIntoACompactField"
              "LedgeClimbTest.OdeClimbsTheLedgeSampledIntoStoredPrisms"
              "VehicleScenesTest.ASkidSteerTurnsInPlaceAlikeAtEveryStepInEveryEngine"
              "RoverScenesTest.ClimbsALowStepInBothEnginesAndModes"
              "SoilTestBedTest.TheRearWheelsRunInTheFrontWheelsRutsAsTheModelPredicts"
              "SoilTestBedTest.EachWheelSettlesAtTheSoilsSteadyStateInBothEngines"
              "SoilVehiclesTest.EachSoilSceneSucceedsAndTheGroundCarriesTheVehicleInBothEnginesAndModes"
              "SoilVehiclesTest.ASecondRoverDrivesInTheRutsTheFirstOneLeaves"
              "SoilVehiclesTest.TheTowedSystemStallsOnLoamWhereTheSoilsSteadyStatesSay"
              "VehicleScenesTest.BulletAndOdeAgreeOnTheDistanceDrivenOverRoughGround"
              "UrdfEquivalenceTest.TowedPathSeriesFromUrdfEqualTheYamlSystemsInBothEnginesAndModes")
list(JOIN long_runs "|" long_runs)
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir ${BUILD_DIR} -j2 --output-on-failure -E "${long_runs}"
                        -LE "cluster|page" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the sanitized suite failed (${rc}): see the reports above")
endif()
