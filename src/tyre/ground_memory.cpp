// The memory of a terrain's soft ground (design in wtc/tyre/ground_memory.hpp).
#include "wtc/tyre/ground_memory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "ground_memory_access.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {

struct GroundMemory::Impl {
  std::vector<detail::SoilGrid> grids;
  /// The region's grid holding world (x, y), or null outside every region.
  detail::SoilGrid* gridAt(double x, double y) {
    for (detail::SoilGrid& grid : grids) {
      if (grid.contains(x, y)) return &grid;
    }
    return nullptr;
  }
};

GroundMemory::GroundMemory(const Terrain& terrain) : impl_(std::make_unique<Impl>()) {
  for (const SoilRegion& region : terrain.soilRegions()) impl_->grids.emplace_back(region);
}

GroundMemory::~GroundMemory() = default;
GroundMemory::GroundMemory(GroundMemory&&) noexcept = default;
GroundMemory& GroundMemory::operator=(GroundMemory&&) noexcept = default;

std::size_t GroundMemory::regionCount() const { return impl_->grids.size(); }

SoilMemory GroundMemory::at(double x, double y) const {
  const detail::SoilGrid* grid = impl_->gridAt(x, y);
  return grid != nullptr ? detail::memoryOf(grid->sample(x, y)) : SoilMemory{};
}

std::size_t GroundMemory::touchedNodes() const {
  std::size_t sum = 0;
  for (const detail::SoilGrid& grid : impl_->grids) sum += grid.touchedNodes();
  return sum;
}

void GroundMemory::forEachTouchedNode(
    const std::function<void(double x, double y, const SoilMemory& memory)>& visit) const {
  for (const detail::SoilGrid& grid : impl_->grids) {
    const SoilRegion& spec = grid.spec();
    grid.forEachTouched([&](int i, int j, const detail::SoilNode& node) {
      const Eigen::Vector2d at = spec.origin + spec.spacing * Eigen::Vector2d(i, j);
      visit(at.x(), at.y(), detail::memoryOf(node));
    });
  }
}

std::size_t GroundMemory::bytes() const {
  std::size_t sum = 0;
  for (const detail::SoilGrid& grid : impl_->grids) sum += grid.bytes();
  return sum;
}

bool GroundMemory::setNode(double x, double y, const SoilMemory& memory) {
  constexpr double kFloatMax = std::numeric_limits<float>::max();
  if (!(std::abs(memory.plastic_sinkage) <= kFloatMax) ||
      !(memory.max_pressure >= 0.0 && memory.max_pressure <= kFloatMax)) {
    return false;  // not finite, beyond a float, or a negative pressure
  }
  detail::SoilGrid* grid = impl_->gridAt(x, y);
  if (grid == nullptr) return false;
  const SoilRegion& spec = grid->spec();
  const double u = (x - spec.origin.x()) / spec.spacing, v = (y - spec.origin.y()) / spec.spacing;
  const double i = std::round(u), j = std::round(v);
  if (std::abs(u - i) > tolerance::kSoilNodeRelative || std::abs(v - j) > tolerance::kSoilNodeRelative) return false;
  grid->set(static_cast<int>(i), static_cast<int>(j),
            {static_cast<float>(memory.plastic_sinkage), static_cast<float>(memory.max_pressure)});
  return true;
}

void GroundMemory::clear() {
  for (detail::SoilGrid& grid : impl_->grids) grid = detail::SoilGrid(grid.spec());
}

namespace detail {

SoilGrid* GroundMemoryAccess::gridAt(GroundMemory& memory, double x, double y) { return memory.impl_->gridAt(x, y); }

namespace {

// How far raised soil may slide from the rut, in nodes: a berm a few
// nodes wide (its slope is settled within a step's few passes).
constexpr int kMaxSlideNodes = 8;
// A slide smaller than this is settled (m): a float's resolution on a
// rut's centimetres.
constexpr double kSettledSlideM = 1e-7;

// Raises the node nearest `at` by `height` (m; a negative plastic
// sinkage), then lets the raised soil slide outward, node by node along
// `outward`, wherever a node stands above its outer neighbour by more than
// the angle of repose allows over their distance: the excess is shared so
// that the pair stands exactly at the slope, the volume (height times the
// equal node areas) kept. Sweeps repeat until none moves (lowering a node
// steepens the pair inside it). The slide stops at the region's edge.
void bulldoze(SoilGrid& grid, const Eigen::Vector2d& at, const Eigen::Vector2d& outward, double height) {
  const SoilRegion& spec = grid.spec();
  std::array<Eigen::Vector2i, kMaxSlideNodes + 1> chain;
  int nodes = 0;
  for (int k = 0; k <= kMaxSlideNodes; ++k) {
    const Eigen::Vector2d u = (at + k * spec.spacing * outward - spec.origin) / spec.spacing;
    const Eigen::Vector2i n(static_cast<int>(std::lround(u.x())), static_cast<int>(std::lround(u.y())));
    if (n.x() < 0 || n.y() < 0 || n.x() >= grid.columns() || n.y() >= grid.rows()) break;
    if (nodes > 0 && n == chain[nodes - 1]) continue;
    chain[nodes++] = n;
  }
  if (nodes == 0) return;
  const auto sinkage = [&](int k) { return grid.node(chain[k].x(), chain[k].y()).plastic_sinkage; };
  const auto raise = [&](int k, double by) {
    SoilNode node = grid.node(chain[k].x(), chain[k].y());
    node.plastic_sinkage = static_cast<float>(node.plastic_sinkage - by);
    grid.set(chain[k].x(), chain[k].y(), node);
  };
  raise(0, height);
  const double slope = std::tan(spec.repose_angle_deg * std::numbers::pi / 180.0);
  for (int sweep = 0; sweep < kMaxSlideNodes; ++sweep) {
    bool moved = false;
    for (int k = 0; k + 1 < nodes; ++k) {
      const double run = spec.spacing * (chain[k + 1] - chain[k]).cast<double>().norm();
      // How far node k stands above node k + 1 beyond the slope.
      const double excess = sinkage(k + 1) - sinkage(k) - slope * run;
      if (!(excess > kSettledSlideM)) continue;
      raise(k, -0.5 * excess);
      raise(k + 1, 0.5 * excess);
      moved = true;
    }
    if (!moved) return;
  }
}

}  // namespace

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
      const Eigen::Vector2d at = spec.origin + spec.spacing * Eigen::Vector2d(i, j), d = at - p.bottom;
      const double s = d.dot(p.travel), across = d.dot(side);
      if (std::abs(across) > half || s > ahead || s < behind) continue;
      const double offset = p.ball ? s * s + across * across : s * s;
      const double depth = p.depth - (r - std::sqrt(std::max(0.0, r * r - offset)));
      const SoilNode node = grid.node(i, j);
      const SoilMemory before = memoryOf(node);
      const SoilMemory after = pressedSoil(soil, p.width, before, depth);
      if (after.plastic_sinkage == before.plastic_sinkage && !(after.max_pressure > node.max_pressure)) continue;
      const SoilNode pressed{static_cast<float>(after.plastic_sinkage), static_cast<float>(after.max_pressure)};
      grid.set(i, j, pressed);
      const double drop = static_cast<double>(pressed.plastic_sinkage) - node.plastic_sinkage;
      if (spec.flow_factor > 0.0 && drop > 0.0) {
        const Eigen::Vector2d outward = (across >= 0.0 ? 1.0 : -1.0) * side;
        bulldoze(grid, at + (half + spec.spacing - std::abs(across)) * outward, outward, spec.flow_factor * drop);
      }
    }
  }
}

}  // namespace detail
}  // namespace wtc
