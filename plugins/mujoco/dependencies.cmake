# What wtc::mujoco needs, found alike in the build (wtc_add_engine) and in the installed package (wtcConfig.cmake
# includes this file as wtc_mujoco_dependencies.cmake). Debian's libmujoco-dev ships MuJoCo's own CMake package.
find_package(mujoco 2.2 CONFIG REQUIRED)
