#pragma once
// A seeded heightfield for the terrain tests: heights uniform in
// [-amplitude, amplitude] from the raw mt19937 stream (fully specified by
// the standard, unlike its distributions), on the grid given.
#include <cstdint>
#include <random>

#include <Eigen/Core>

#include "wtc/heightfield.hpp"

namespace wtc::testing {

struct RandomGrid {
  double spacing_x = 0.5, spacing_y = 0.75;  // (m)
  Eigen::Vector3d origin{-3.0, 2.0, 10.0};   // (m)
  double base_depth = 0.4;                   // (m)
};

inline Heightfield randomHeightfield(int rows, int cols, double amplitude, std::uint32_t seed,
                                     const RandomGrid& grid = {}) {
  std::mt19937 gen(seed);
  Heightfield f;
  f.rows = rows;
  f.cols = cols;
  f.spacing_x = grid.spacing_x;
  f.spacing_y = grid.spacing_y;
  f.origin = grid.origin;
  f.base_depth = grid.base_depth;
  for (int i = 0; i < rows * cols; ++i) f.heights.push_back(amplitude * (2.0 * (gen() / 4294967296.0) - 1.0));
  return f;
}

}  // namespace wtc::testing
