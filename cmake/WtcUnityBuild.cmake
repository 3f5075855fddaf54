# Unity builds by default, for the main build and the fuzz build alike: a
# translation unit per batch of 8 files compiles the headers they share once
# (docs/development.md and docs/fuzzing.md measure each build both ways). A
# developer who rebuilds after editing one file may prefer
# -DCMAKE_UNITY_BUILD=OFF, one unit per file. Included before any target.
if(NOT DEFINED CMAKE_UNITY_BUILD)
  set(CMAKE_UNITY_BUILD ON)
endif()
