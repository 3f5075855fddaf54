# What wtc::bullet needs, found alike in the build (wtc_add_engine) and in the installed package (wtcConfig.cmake
# includes this file as wtc_bullet_dependencies.cmake). Bullet ships float and double builds; WTC is double
# throughout. The .pc file adds -DBT_USE_DOUBLE_PRECISION; never link the float build as well.
find_package(PkgConfig REQUIRED)
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET GLOBAL bullet-float64)
