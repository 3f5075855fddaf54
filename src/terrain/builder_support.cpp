#include "builder_support.hpp"

#include "geometry/polyhedron_layout.hpp"
#include "geometry/prism_kernel.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "wtc/base/error.hpp"

namespace wtc::detail {

namespace {

// Vertices 0-2 the top triangle, 3-5 the bottom one. The top keeps its
// winding, the bottom is reversed (seen from below), and the side quad on
// edge i -> j runs i, i', j', j: with the top normal up, (i' - i) x (j' - i)
// points away from the third vertex, i.e. outward.
// The lists are the point query's prism kernel's (geometry/prism_kernel.hpp,
// kPrismStart and kPrismList): one definition, so every prism built here
// takes that kernel.
const std::vector<std::vector<int>> kPrismFaces = [] {
  std::vector<std::vector<int>> faces(detail::kPrismFaceCount);
  for (int f = 0; f < detail::kPrismFaceCount; ++f) {
    faces[f].assign(detail::kPrismList + detail::kPrismStart[f], detail::kPrismList + detail::kPrismStart[f + 1]);
  }
  return faces;
}();

// One scratch list per thread: a heightfield adds 10^6 prisms, and this
// keeps the builder to the allocations of the piece itself.
const std::vector<Eigen::Vector3d>& prismVertices(const std::array<Eigen::Vector3d, 3>& top,
                                                  const std::array<Eigen::Vector3d, 3>& bottom) {
  thread_local std::vector<Eigen::Vector3d> vertices(6);
  for (int i = 0; i < 3; ++i) {
    vertices[i] = top[i];
    vertices[i + 3] = bottom[i];
  }
  return vertices;
}

}  // namespace

ConvexPolyhedron makePrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom) {
  return ConvexPolyhedron::fromMesh(prismVertices(top, bottom), kPrismFaces);
}

namespace {

// The prism whose topology every checked prism copies.
const ConvexPolyhedron& referencePrism() {
  static const ConvexPolyhedron kReference =
      makePrism({Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(0, 1, 1)},
                {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)});
  return kReference;
}

}  // namespace

// referencePrism() is called before prismVertices: its first call builds
// the reference through the same per-thread vertex list.
ConvexPolyhedron makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top,
                                  const std::array<Eigen::Vector3d, 3>& bottom) {
  const ConvexPolyhedron& like = referencePrism();
  return PolyhedronLayout::sameTopologyAs(like, prismVertices(top, bottom), kPrismFaces);
}

void makeCheckedPrism(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom,
                      ConvexPolyhedron& into) {
  const ConvexPolyhedron& like = referencePrism();
  PolyhedronLayout::sameTopologyInto(into, like, prismVertices(top, bottom), kPrismFaces);
}

}  // namespace wtc::detail
