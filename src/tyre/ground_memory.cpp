// The memory of a terrain's soft ground (design in wtc/tyre/ground_memory.hpp).
#include "wtc/tyre/ground_memory.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ground_memory_access.hpp"

namespace wtc {

struct GroundMemory::Impl {
  std::vector<detail::SoilGrid> grids;
};

GroundMemory::GroundMemory(const Terrain& terrain) : impl_(std::make_unique<Impl>()) {
  for (const SoilRegion& region : terrain.soilRegions()) impl_->grids.emplace_back(region);
}

GroundMemory::~GroundMemory() = default;
GroundMemory::GroundMemory(GroundMemory&&) noexcept = default;
GroundMemory& GroundMemory::operator=(GroundMemory&&) noexcept = default;

std::size_t GroundMemory::regionCount() const { return impl_->grids.size(); }

SoilMemory GroundMemory::at(double x, double y) const {
  for (const detail::SoilGrid& grid : impl_->grids) {
    if (grid.contains(x, y)) return detail::memoryOf(grid.sample(x, y));
  }
  return {};
}

std::size_t GroundMemory::touchedNodes() const {
  std::size_t sum = 0;
  for (const detail::SoilGrid& grid : impl_->grids) sum += grid.touchedNodes();
  return sum;
}

std::size_t GroundMemory::bytes() const {
  std::size_t sum = 0;
  for (const detail::SoilGrid& grid : impl_->grids) sum += grid.bytes();
  return sum;
}

void GroundMemory::clear() {
  for (detail::SoilGrid& grid : impl_->grids) grid = detail::SoilGrid(grid.spec());
}

namespace detail {

SoilGrid* GroundMemoryAccess::gridAt(GroundMemory& memory, double x, double y) {
  for (SoilGrid& grid : memory.impl_->grids) {
    if (grid.contains(x, y)) return &grid;
  }
  return nullptr;
}

void pressNodes(SoilGrid& grid, const Soil& soil, const RimPress& p) {
  const double r = p.radius, half = 0.5 * p.width;
  const double ahead = p.at_rest * r * std::sin(p.entry_angle), behind = -r * std::sin(p.entry_angle);
  const Eigen::Vector2d side(-p.travel.y(), p.travel.x());
  // The band's box in node coordinates.
  const Eigen::Vector2d reach = (ahead - behind) * p.travel.cwiseAbs() + p.width * side.cwiseAbs();
  const Eigen::Vector2d centre = p.bottom + 0.5 * (ahead + behind) * p.travel;
  const SoilRegion& spec = grid.spec();
  const Eigen::Vector2d lo = (centre - 0.5 * reach - spec.origin) / spec.spacing;
  const Eigen::Vector2d hi = (centre + 0.5 * reach - spec.origin) / spec.spacing;
  const int i0 = std::max(0, static_cast<int>(std::ceil(lo.x())));
  const int j0 = std::max(0, static_cast<int>(std::ceil(lo.y())));
  const int i1 = std::min(grid.columns() - 1, static_cast<int>(std::floor(hi.x())));
  const int j1 = std::min(grid.rows() - 1, static_cast<int>(std::floor(hi.y())));
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Eigen::Vector2d d = spec.origin + spec.spacing * Eigen::Vector2d(i, j) - p.bottom;
      const double s = d.dot(p.travel);
      if (std::abs(d.dot(side)) > half || s > ahead || s < behind) continue;
      const double depth = p.depth - (r - std::sqrt(std::max(0.0, r * r - s * s)));
      const SoilNode node = grid.node(i, j);
      const SoilMemory before = memoryOf(node);
      const SoilMemory after = pressedSoil(soil, p.width, before, depth);
      if (after.plastic_sinkage != before.plastic_sinkage || after.max_pressure > node.max_pressure) {
        grid.set(i, j, {static_cast<float>(after.plastic_sinkage), static_cast<float>(after.max_pressure)});
      }
    }
  }
}

}  // namespace detail
}  // namespace wtc
