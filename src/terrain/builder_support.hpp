#pragma once
// Shared by the terrain builders (primitives, heightfields, triangle meshes):
// the prism every surface triangle becomes. Internal to wtc::core.
#include <Eigen/Geometry>
#include <array>
#include <string>

#include "wtc/base/checks.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

/// The prism with triangle `top` (counter-clockwise seen from outside, i.e.
/// from the side its normal (top1 - top0) x (top2 - top0) points to) and
/// `bottom`, bottom[i] lying under top[i]. Precondition: the six points
/// bound a convex solid whose side faces are planar (a right prism, or a
/// vertical prism cut by two planes). Built with the trusted
/// ConvexPolyhedron::fromMesh path, which still validates the result.
ConvexPolyhedron makePrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom);
/// makePrism's piece, bit for bit, for corners already checked (finite, the
/// top above the bottom): the prism's topology is copied from a reference
/// prism instead of matched anew. For prisms formed on demand.
ConvexPolyhedron makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top,
                                  const std::array<Eigen::Vector3d, 3>& bottom);
/// The same prism made into `into`, reusing its buffers (a prism's).
void makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom,
                      ConvexPolyhedron& into);

}  // namespace wtc::detail
