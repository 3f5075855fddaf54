#pragma once
// A triangle mesh kept as its vertices and triangles (internal to
// wtc::core): the prisms of addTriangleMesh (wtc/terrain/triangle_mesh.hpp) are
// formed when asked for, not stored.
//
// A stored prism is a ConvexPolyhedron of about 1.2 kB plus its index
// entry; here a triangle costs its three vertex indices (12 bytes) and its
// share of the vertices (24 bytes each, shared by about six triangles in a
// surface mesh; addTriangleMesh welds exact repeats first, so an STL file's
// copies are kept once). piece(k) is bit for bit the prism addTriangleMesh
// adds as its k-th piece, pieceBounds(k) its bounds(). The index is a
// BoxTree over the pieces' boxes, and each piece's box in single precision
// rounded outward (24 bytes a triangle): it rejects a piece for sure, and
// accepts one for sure when the box shrunk by its rounding still overlaps;
// only the rare box within a rounding of the query's edge is decided on the
// exact box, computed from the triangle (a square root and a division,
// which computed for every leaf member made the rolling step 2.6 times
// slower than on stored prisms: docs/terrain.md).
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "box_tree.hpp"
#include "formed_pieces.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc::detail {

/// The bottom corners of the right prism under triangle (a, b, c): each
/// corner moved `thickness` (m) along minus the unit normal. The one rule
/// for stored (makeExtrudedTriangle) and formed prisms.
std::array<Eigen::Vector3d, 3> extrudedBottom(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                              const Eigen::Vector3d& c, double thickness);

class CompactTriangleMesh final : public FormedPieces {
 public:
  /// `mesh`'s triangles are the pieces in order: finite vertices, wound
  /// outward, none degenerate (addTriangleMesh's checks, done by the caller).
  CompactTriangleMesh(TriangleMesh mesh, double thickness);

  std::size_t pieceCount() const override { return mesh_.triangles.size(); }
  /// makeExtrudedTriangle's corners for triangle k.
  void prismCorners(std::size_t k, std::array<Eigen::Vector3d, 3>& top,
                    std::array<Eigen::Vector3d, 3>& bottom) const override;
  void overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const override;
  const Aabb& bounds() const override { return bounds_; }
  std::size_t memoryBytes() const override;
  std::size_t indexMemoryBytes() const override;
  const TriangleMesh* mesh() const override { return &mesh_; }
  double thickness() const override { return thickness_; }

 private:
  TriangleMesh mesh_;
  double thickness_ = 0.0;
  struct FloatBox {
    float min[3], max[3];
  };
  std::vector<std::int32_t> order_;  // triangle indices in tree order
  std::vector<FloatBox> boxes_;      // their boxes, rounded outward, in tree order
  BoxTree tree_;
  Aabb bounds_;
};

}  // namespace wtc::detail
