#pragma once
// Prisms a builder adds as stored pieces but makes only when the terrain is
// built, each straight into its place in the terrain's arena (internal to
// wtc::core). Made one by one as they were added, a heightfield's 10^6
// prisms were 10^6 blocks of their own that the arena then copied in the
// index's order (piece_arena.hpp): a gigabyte allocated, written and freed
// for nothing, and twice the memory at the peak. Kept instead: how to make
// each, its corners (what makeCheckedPrism takes), already checked by the
// builder that added them; the pieces are those addHeightfield and
// addTriangleMesh stored before, bit for bit.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <functional>

namespace wtc::detail {

struct PendingPrisms {
  /// Prism k's top and bottom corners (k < count), as makeCheckedPrism
  /// takes them.
  using Corners = std::function<void(std::size_t k, std::array<Eigen::Vector3d, 3>& top,
                                     std::array<Eigen::Vector3d, 3>& bottom)>;
  std::size_t first = 0;  ///< the stored position of prism 0
  std::size_t count = 0;
  Corners corners;
};

}  // namespace wtc::detail
