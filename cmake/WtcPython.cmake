# The Python package `wtc` (python/, pybind11): on by default when Python's
# headers and pybind11 are found (Debian: python3-dev, pybind11-dev;
# tools/install-deps.sh), off with -DWTC_BUILD_PYTHON=OFF.
#
# Which Python: Debian's /usr/bin/python3 when it exists, the interpreter
# whose packages (python3-numpy, python3-pytest, python3-matplotlib)
# tools/install-deps.sh installs, even when another python3 comes first on
# PATH (a pyenv's); -DPython3_EXECUTABLE=... chooses another. Every
# find_package(Python3) of the project (the tests run scripts with
# ${Python3_EXECUTABLE}) then finds that one.
option(WTC_BUILD_PYTHON "Build the Python package wtc (needs Python's headers and pybind11)" ON)
if(NOT Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python interpreter the project builds and tests for")
endif()
