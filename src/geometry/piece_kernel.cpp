// Which query kernel fits a piece (piece_kernel.hpp): each kernel's
// conditions checked on the stored numbers themselves, exactly, so that the
// kernel's shortened arithmetic is the general arithmetic's to the bit.
#include "piece_kernel.hpp"

#include "box_kernel.hpp"
#include "prism_kernel.hpp"

namespace wtc::detail {
namespace {

using Layout = PolyhedronLayout;

// An axis-aligned box in ConvexPolyhedron::box's layout: its face lists,
// vertex i at (bit 0 ? hi : lo) per axis with lo < 0 < hi, face normals
// exactly -+ the axes (other components zero), offsets d != 0, and each
// side plane zero but on boxSideAxis.
bool isAxisBox(const ConvexPolyhedron& poly) {
  if (poly.vertexCount() != 8 || poly.faceCount() != 6 || poly.isFlat()) return false;
  for (int f = 0; f < 6; ++f) {
    if (Layout::faceSize(poly, f) != 4 || Layout::faceEdgeStart(poly, f) != 4 * f) return false;
    const std::int32_t* list = Layout::faceVertexList(poly, f);
    for (int k = 0; k < 4; ++k) {
      if (list[k] != kBoxFaces[f][k]) return false;
    }
  }
  const Eigen::Vector3d lo = poly.vertexLocal(0);
  const Eigen::Vector3d hi = poly.vertexLocal(7);
  for (int axis = 0; axis < 3; ++axis) {
    if (!(lo[axis] < 0.0 && hi[axis] > 0.0)) return false;
  }
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d v = poly.vertexLocal(i);
    for (int axis = 0; axis < 3; ++axis) {
      if (v[axis] != ((i >> axis) & 1 ? hi[axis] : lo[axis])) return false;
    }
  }
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const double sign = f % 2 == 0 ? -1.0 : 1.0;
    const Eigen::Vector3d n = poly.faceNormal(f);
    for (int c = 0; c < 3; ++c) {
      if (n[c] != (c == axis ? sign : 0.0)) return false;
    }
    if (Layout::pd(poly)[f] == 0.0) return false;
    const double* side = Layout::faceEdgePlanes(poly, f);
    for (int k = 0; k < 4; ++k, side += 4) {
      for (int c = 0; c < 3; ++c) {
        if ((side[c] != 0.0) != (c == boxSideAxis(f, k))) return false;
      }
    }
  }
  return true;
}

// The terrain builders' prism: its face lists, solid. The twins and the
// neighbours follow from the face lists of a closed piece (fromMesh and the
// copied topology of the formed prisms guarantee it).
bool isBuildersPrism(const ConvexPolyhedron& poly) {
  if (poly.vertexCount() != 6 || poly.faceCount() != kPrismFaceCount || poly.isFlat()) return false;
  for (int f = 0; f < kPrismFaceCount; ++f) {
    if (Layout::faceEdgeStart(poly, f) != kPrismStart[f] ||
        Layout::faceSize(poly, f) != kPrismStart[f + 1] - kPrismStart[f]) {
      return false;
    }
  }
  const std::int32_t* list = Layout::faceVertexList(poly, 0);
  for (int e = 0; e < kPrismFaceEdges; ++e) {
    if (list[e] != kPrismList[e]) return false;
  }
  return true;
}

// A builders' prism that stands upright on a flat bottom: side normals with
// n_z = 0, the bottom's (0, 0, -1), and each side plane zero where
// kUprightSideTerms drops it.
bool isUpright(const ConvexPolyhedron& poly) {
  const double* nx = Layout::nx(poly);
  const double* ny = Layout::ny(poly);
  const double* nz = Layout::nz(poly);
  if (!(nx[1] == 0.0 && ny[1] == 0.0 && nz[1] == -1.0)) return false;
  for (int f = 2; f < kPrismFaceCount; ++f) {
    if (nz[f] != 0.0) return false;
  }
  const double* side = Layout::faceEdgePlanes(poly, 0);
  for (int e = 0; e < kPrismFaceEdges; ++e, side += 4) {
    if (kUprightSideTerms[e] == SideTerms::kXY && side[2] != 0.0) return false;
    if (kUprightSideTerms[e] == SideTerms::kZ && (side[0] != 0.0 || side[1] != 0.0)) return false;
  }
  return true;
}

}  // namespace

PieceKernel kernelFor(const ConvexPolyhedron& poly) {
  if (isAxisBox(poly)) return PieceKernel::kAxisBox;
  if (isBuildersPrism(poly)) return isUpright(poly) ? PieceKernel::kUprightPrism : PieceKernel::kPrism;
  return PieceKernel::kGeneral;
}

}  // namespace wtc::detail
