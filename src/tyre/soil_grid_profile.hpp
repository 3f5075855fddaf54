#pragma once
// The ground's memory along a wheel's travel, read from a soil region's grid
// (internal to wtc::core; issue 55): the nodes' plastic sinkage and largest
// pressure interpolated at the point `ahead` of the rim's lowest point
// along the travel. A point among untouched nodes is fresh.
#include <Eigen/Core>

#include "terrain/soil_grid.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc::detail {

/// A node as the stresses read it: a node written carried a load (its
/// pressure is positive, bfloat16 rounding up), so zeros are ground no
/// wheel has pressed: fresh.
inline SoilMemory memoryOf(const SoilNode& n) {
  const bool fresh = n.max_pressure == 0.0f && n.plastic_sinkage == 0.0f;
  return {.plastic_sinkage = n.plastic_sinkage, .max_pressure = n.max_pressure, .fresh = fresh};
}

class GridProfile final : public SoilMemoryProfile {
 public:
  /// `bottom`: the ground point under the rim's lowest point (world x, y);
  /// `travel`: the travel's horizontal direction (unit).
  GridProfile(const SoilGrid& grid, const Eigen::Vector2d& bottom, const Eigen::Vector2d& travel)
      : grid_(grid), bottom_(bottom), travel_(travel) {}

  SoilMemory at(double ahead) const override {
    const Eigen::Vector2d p = bottom_ + ahead * travel_;
    return memoryOf(grid_.sample(p.x(), p.y()));
  }

  /// Beside the line along the axle laid on the ground, n x t: the travel
  /// turned a quarter left.
  SoilMemory beside(double ahead, double aside) const override {
    const Eigen::Vector2d side(-travel_.y(), travel_.x());
    const Eigen::Vector2d p = bottom_ + ahead * travel_ + aside * side;
    return memoryOf(grid_.sample(p.x(), p.y()));
  }

 private:
  const SoilGrid& grid_;
  Eigen::Vector2d bottom_, travel_;
};

}  // namespace wtc::detail
